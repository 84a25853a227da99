#include <mbfem/base/files.h>
#include <mbfem/contact/contact_problem.h>
#include <mbfem/contact/contact_solver.h>

#include <cstdio>
#include <sstream>

namespace mbfem
{
  namespace
  {
    /** 17 significant digits: the file reproduces the doubles. */
    std::string
    number(const double x)
    {
      char buffer[32];
      std::snprintf(buffer, sizeof(buffer), "%.17g", x);
      return buffer;
    }

    template <typename T, typename F>
    std::string
    json_list(const std::vector<T> &values, const F &format)
    {
      std::string text = "[";
      for (unsigned int i = 0; i < values.size(); ++i)
        text += (i > 0 ? ", " : "") + format(values[i]);
      return text + "]";
    }

    std::string
    json_numbers(const std::vector<double> &values)
    {
      return json_list(values, number);
    }

    /** Matrix Market, coordinate real general, 1-based. */
    std::string
    matrix_market(
      const unsigned int                                             m,
      const unsigned int                                             n,
      const std::map<std::pair<unsigned int, unsigned int>, double> &entries)
    {
      std::ostringstream text;
      text << "%%MatrixMarket matrix coordinate real general\n"
           << m << " " << n << " " << entries.size() << "\n";
      for (const auto &[index, value] : entries)
        text << index.first + 1 << " " << index.second + 1 << " "
             << number(value) << "\n";
      return text.str();
    }



    /** The JSON fields of the pairs' data (mu to direction_stiffness). */
    template <int dim>
    std::string
    pair_fields(const std::vector<typename ContactProblem<dim>::Pair> &pairs)
    {
      using Pair       = typename ContactProblem<dim>::Pair;
      const auto field = [&](const auto &get) {
        std::vector<std::string> values;
        for (const auto &pair : pairs)
          values.push_back(get(pair));
        return json_list(values, [](const std::string &s) { return s; });
      };
      const auto vector = [](const auto &t) {
        std::string text = "[";
        for (unsigned int d = 0; d < dim; ++d)
          text += (d > 0 ? ", " : "") + number(t[d]);
        return text + "]";
      };
      std::ostringstream json;
      // The law as the linear cone Lemke's method and the scripts solve:
      // mu, c A and sigma_t A (0 once broken).
      json << "  \"mu\": " << field([](const Pair &p) {
        return number(p.joint.slip_line(p.area, p.broken).slope);
      }) << ",\n"
           << "  \"cohesion\": " << field([](const Pair &p) {
                return number(p.joint.slip_line(p.area, p.broken).intercept);
              })
           << ",\n"
           << "  \"tension\": " << field([](const Pair &p) {
                return number(p.joint.tensile_limit(p.area, p.broken));
              })
           << ",\n"
           << "  \"area\": "
           << field([](const Pair &p) { return number(p.area); }) << ",\n"
           << "  \"point\": "
           << field([&](const Pair &p) { return vector(p.point); }) << ",\n"
           << "  \"frame\": " << field([&](const Pair &p) {
                std::string text = "[";
                for (unsigned int i = 0; i < dim; ++i)
                  text += (i > 0 ? ", " : "") + vector(p.frame[i]);
                return text + "]";
              })
           << ",\n"
           << "  \"state\": "
           << field([](const Pair &p) { return "\"" + p.state + "\""; })
           << ",\n"
           << "  \"broken\": " << field([](const Pair &p) {
                return std::string(p.broken ? "1" : "0");
              })
           << ",\n"
           << "  \"tensile_slip\": " << field([](const Pair &p) {
                return std::string(p.tensile_slip ? "1" : "0");
              })
           << ",\n"
           << "  \"tied\": " << field([](const Pair &p) {
                return std::string(p.tied ? "1" : "0");
              })
           << ",\n"
           << "  \"held\": " << field([](const Pair &p) {
                std::string text = "[";
                for (unsigned int d = 0; d < dim; ++d)
                  text +=
                    std::string(d > 0 ? ", " : "") + (p.held[d] ? "1" : "0");
                return text + "]";
              })
           << ",\n"
           << "  \"slip_direction\": "
           << field([&](const Pair &p) { return vector(p.slip_direction); })
           << ",\n"
           << "  \"direction_stiffness\": "
           << field([](const Pair &p) { return number(p.direction_stiffness); })
           << ",\n";
      return json.str();
    }
  } // namespace



  template <int dim>
  void
  ContactProblem<dim>::write(const std::string &stem) const
  {
    const unsigned int n_r = n_pairs * dim;
    write_file_atomically(stem + "-W.mtx", matrix_market(n_r, n_r, W));
    std::map<std::pair<unsigned int, unsigned int>, double> g;
    for (unsigned int i = 0; i < G.m(); ++i)
      for (unsigned int a = 0; a < G.n(); ++a)
        if (G(i, a) != 0.)
          g[{i, a}] = G(i, a);
    write_file_atomically(stem + "-G.mtx", matrix_market(n_r, n_alpha, g));

    const std::string  name = stem.substr(stem.find_last_of('/') + 1);
    std::ostringstream json;
    json
      << "{\n"
      << "  \"format\": \"mbfem contact problem 1 (doc/contact_problems.md)\",\n"
      << "  \"convention\": \"u = W r + q + G alpha, G^T r + f = 0; per "
         "pair normal first\",\n"
      << "  \"dimension\": " << dim << ",\n"
      << "  \"increment\": " << increment << ",\n"
      << "  \"time\": " << number(time) << ",\n"
      << "  \"n_pairs\": " << n_pairs << ",\n"
      << "  \"n_alpha\": " << n_alpha << ",\n"
      << "  \"W\": \"" << name << "-W.mtx\",\n"
      << "  \"G\": \"" << name << "-G.mtx\",\n"
      << "  \"q\": " << json_numbers(q) << ",\n"
      << "  \"f\": " << json_numbers(f) << ",\n"
      << pair_fields<dim>(pairs)
      << "  \"solved\": " << (r.empty() ? "false" : "true") << ",\n"
      << "  \"r\": " << json_numbers(r) << ",\n"
      << "  \"alpha\": " << json_numbers(alpha) << ",\n"
      << "  \"u\": " << json_numbers(u) << "\n"
      << "}\n";
    write_file_atomically(stem + ".json", json.str());
  }



  template <int dim>
  ContactProblem<dim>
  ContactSolver<dim>::condensed_problem(const unsigned int increment,
                                        const double       time,
                                        const bool         solved,
                                        const bool with_flexibility) const
  {
    AssertThrow(!monolithic,
                ExcMessage("Output/Write contact problems: the condensed "
                           "problem exists for the condensed formulation "
                           "only (Contact/Formulation = condensed or "
                           "both)."));
    ContactProblem<dim> problem;
    problem.increment  = increment;
    problem.time       = time;
    problem.n_pairs    = n_pairs;
    problem.n_alpha    = coupling.n_modes();
    const unsigned n_r = n_pairs * dim;
    // W = C_hat: the sum over the blocks two pairs share of H_b.
    if (with_flexibility)
      condensed->add_entries(problem.W);
    problem.G.reinit(n_r, coupling.n_modes());
    for (unsigned int i = 0; i < n_r; ++i)
      for (const auto &[a, value] : coupling.row(i))
        problem.G(i, a) = value;
    problem.f = loads.resultant;
    problem.f.resize(coupling.n_modes(), 0.);

    // q: u_N is the gap g0 + d_N, u_T the increment d_T - d_T(committed).
    const Trial &trial = solved ? current : committed;
    problem.q.resize(n_r);
    for (unsigned int k = 0; k < n_pairs; ++k)
      {
        const auto &pair = contact_pairs[k];
        for (unsigned int d = 0; d < dim; ++d)
          problem.q[k * dim + d] =
            loads.displacement(k * dim + d) +
            (d == 0 ? pair.initial_gap : -committed_displacement[k][d]);
        typename ContactProblem<dim>::Pair data;
        data.point        = pair.midpoint();
        data.area         = pair.area;
        data.broken       = trial.broken[k];
        data.tensile_slip = trial.tensile_slip[k];
        data.joint        = pair.joint;
        data.frame        = pair.frame;
        data.tied         = pair.tied;
        for (unsigned int d = 0; d < dim; ++d)
          data.held[d] = held[k][d];
        data.state = to_string(trial.state[k]);
        data.slip_direction =
          (solved && solved_slip_direction.size() == n_pairs ?
             solved_slip_direction[k] :
             trial.slip_direction[k]);
        data.direction_stiffness = trial.direction_stiffness[k];
        problem.pairs.push_back(data);
      }
    if (solved && current_solution.size() == n_r + coupling.n_modes())
      {
        for (unsigned int i = 0; i < n_r; ++i)
          problem.r.push_back(current_solution(i));
        for (unsigned int a = 0; a < coupling.n_modes(); ++a)
          problem.alpha.push_back(current_solution(n_r + a));
        for (unsigned int k = 0; k < n_pairs; ++k)
          for (unsigned int d = 0; d < dim; ++d)
            problem.u.push_back(d == 0 ? gap(k) :
                                         current_displacement[k][d] -
                                           committed_displacement[k][d]);
      }
    return problem;
  }



  template struct ContactProblem<2>;
  template struct ContactProblem<3>;
  template ContactProblem<2>
  ContactSolver<2>::condensed_problem(const unsigned int,
                                      const double,
                                      const bool,
                                      const bool) const;
  template ContactProblem<3>
  ContactSolver<3>::condensed_problem(const unsigned int,
                                      const double,
                                      const bool,
                                      const bool) const;
} // namespace mbfem
