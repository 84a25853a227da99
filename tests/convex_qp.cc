// mbfem::ConvexQp (Mehrotra's interior-point method for De Saxce's fixed
// point, doc/decisions.md):
// 1. the projection of a random point p onto the simplex {x >= 0, sum x = 1}
//    (H = I, c = -p, one equality, 40 bounds as rows) equals the closed form
//    x_i = max(p_i - tau, 0) with sum x = 1 (tau by sorting) to 1e-6: the
//    method stops at relative residuals of 1e-10, or of up to 1e3 times
//    that where round-off ends their decrease (ConvexQp::solve()), and
//    with H = I a residual passes to x unchanged: 1e-7 at most, plus the
//    complementarity's mu / z and mu / s (mu about 4e-10, the smallest
//    multiplier 0.12 and slack 0.039 of this draw: 1e-8); 3.1e-8 measured;
// 2. a random convex QP with a singular H = B^T B (rank 10 of 30), 45
//    random rows C x <= d and 5 equalities, built around a known feasible
//    point: its answer meets the KKT conditions (stationarity, A x = b,
//    C x <= d, z >= 0, z_i (d - C x)_i = 0) to 1e-8 of the data's scale;
// 3. x >= 1 and x <= 0 together: not reported optimal.

#include <mbfem/linear_algebra/convex_qp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>

using namespace dealii;
using mbfem::ConvexQp;

namespace
{
  const char *
  yes(const bool b)
  {
    return b ? "yes" : "no";
  }

  void
  simplex_projection(std::mt19937 &random)
  {
    const unsigned int                     n = 40;
    std::uniform_real_distribution<double> uniform(-1., 1.);
    ConvexQp                               qp;
    qp.H.reinit(n, n);
    qp.c.reinit(n);
    qp.A.reinit(1, n);
    qp.b.reinit(1);
    qp.b(0) = 1.;
    std::vector<double> p(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        p[i]       = uniform(random);
        qp.H(i, i) = 1.;
        qp.c(i)    = -p[i];
        qp.A(0, i) = 1.;
        qp.rows.push_back({{{i, -1.}}, 0.});
      }
    // The closed form: tau such that sum max(p_i - tau, 0) = 1.
    std::vector<double> sorted = p;
    std::sort(sorted.begin(), sorted.end(), std::greater<double>());
    double tau = 0., sum = 0.;
    for (unsigned int k = 0; k < n; ++k)
      {
        sum += sorted[k];
        const double t = (sum - 1.) / (k + 1);
        if (k + 1 == n || sorted[k + 1] <= t)
          {
            tau = t;
            break;
          }
      }
    const bool optimal = qp.solve(1e-10) == ConvexQp::Status::optimal;
    double     error   = 0.;
    for (unsigned int i = 0; i < n; ++i)
      error = std::max(error, std::abs(qp.x(i) - std::max(p[i] - tau, 0.)));
    std::printf("simplex projection: optimal %s, equals the closed form to "
                "1e-6: %s\n",
                yes(optimal),
                yes(error < 1e-6));
  }

  void
  random_qp(std::mt19937 &random)
  {
    const unsigned int                     n = 30, rank = 10, m = 5, p = 45;
    std::uniform_real_distribution<double> uniform(-1., 1.);
    ConvexQp                               qp;
    FullMatrix<double>                     B(rank, n);
    for (unsigned int i = 0; i < rank; ++i)
      for (unsigned int j = 0; j < n; ++j)
        B(i, j) = uniform(random);
    qp.H.reinit(n, n);
    B.Tmmult(qp.H, B);
    qp.c.reinit(n);
    for (unsigned int j = 0; j < n; ++j)
      qp.c(j) = uniform(random);
    Vector<double> feasible(n);
    for (unsigned int j = 0; j < n; ++j)
      feasible(j) = uniform(random);
    qp.A.reinit(m, n);
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int j = 0; j < n; ++j)
        qp.A(i, j) = uniform(random);
    qp.b.reinit(m);
    qp.A.vmult(qp.b, feasible);
    // Rows of 3 entries, d such that the feasible point has slack; bounds
    // on every variable keep the problem bounded although H is singular.
    for (unsigned int k = 0; k < p; ++k)
      {
        ConvexQp::Row row;
        double        value = 0.;
        for (unsigned int e = 0; e < 3; ++e)
          {
            const unsigned int j = (k * 7 + e * 11) % n;
            row.entries.emplace_back(j, uniform(random));
            value += row.entries.back().second * feasible(j);
          }
        row.bound = value + 0.5 * (1. + uniform(random));
        qp.rows.push_back(row);
      }
    for (unsigned int j = 0; j < n; ++j)
      {
        qp.rows.push_back({{{j, 1.}}, 2.});
        qp.rows.push_back({{{j, -1.}}, 2.});
      }
    const bool optimal = qp.solve(1e-10) == ConvexQp::Status::optimal;

    Vector<double> stationarity(n), Ax(m);
    qp.H.vmult(stationarity, qp.x);
    stationarity += qp.c;
    qp.A.Tvmult_add(stationarity, qp.y);
    double feasibility = 0., complementarity = 0., sign = 0.;
    for (unsigned int k = 0; k < qp.rows.size(); ++k)
      {
        double cx = 0.;
        for (const auto &[j, a] : qp.rows[k].entries)
          {
            cx += a * qp.x(j);
            stationarity(j) += a * qp.z(k);
          }
        const double slack = qp.rows[k].bound - cx;
        feasibility        = std::max(feasibility, -slack);
        complementarity = std::max(complementarity, std::abs(qp.z(k) * slack));
        sign            = std::max(sign, -qp.z(k));
      }
    qp.A.vmult(Ax, qp.x);
    Ax -= qp.b;
    const double scale = 1. + qp.c.linfty_norm() + qp.H.linfty_norm();
    std::printf("random QP (H of rank %u): optimal %s; stationarity %s, "
                "A x = b %s, C x <= d %s, z >= 0 %s, complementarity %s "
                "(each to 1e-8)\n",
                rank,
                yes(optimal),
                yes(stationarity.linfty_norm() < 1e-8 * scale),
                yes(Ax.linfty_norm() < 1e-8 * scale),
                yes(feasibility < 1e-8 * scale),
                yes(sign < 1e-8 * scale),
                yes(complementarity < 1e-8 * scale));
  }

  void
  infeasible()
  {
    ConvexQp qp;
    qp.H.reinit(1, 1);
    qp.H(0, 0) = 1.;
    qp.c.reinit(1);
    qp.A.reinit(0, 1);
    qp.b.reinit(0);
    qp.rows.push_back({{{0, -1.}}, -1.}); // x >= 1
    qp.rows.push_back({{{0, 1.}}, 0.});   // x <= 0
    std::printf("x >= 1 and x <= 0: reported optimal %s\n",
                yes(qp.solve(1e-10) == ConvexQp::Status::optimal));
  }
} // namespace



int
main()
{
  std::mt19937 random(62);
  simplex_projection(random);
  random_qp(random);
  infeasible();
}
