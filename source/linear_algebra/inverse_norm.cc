#include <mbfem/linear_algebra/inverse_norm.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace mbfem
{
  double
  inverse_norm_estimate(const unsigned int                           n,
                        const std::vector<unsigned int>             &support,
                        const std::function<void(Vector<double> &)> &apply)
  {
    std::vector<unsigned int> entries = support;
    if (entries.empty())
      {
        entries.resize(n);
        std::iota(entries.begin(), entries.end(), 0);
      }
    double inverse_norm = 0.;
    for (unsigned int trial = 0; trial < 2; ++trial)
      {
        Vector<double> probe(n);
        double         probe_norm = 0.;
        for (unsigned int i = 0; i < entries.size(); ++i)
          {
            probe(entries[i]) = std::sin(1.3 + 0.7 * i * (trial + 1)) + 0.1;
            probe_norm += std::abs(probe(entries[i]));
          }
        apply(probe);
        double solution_norm = 0.;
        for (const unsigned int j : entries)
          solution_norm += std::abs(probe(j));
        const double ratio = solution_norm / probe_norm;
        // std::max would drop a NaN.
        if (!std::isfinite(ratio))
          return std::numeric_limits<double>::infinity();
        inverse_norm = std::max(inverse_norm, ratio);
      }
    return inverse_norm;
  }
} // namespace mbfem
