#include <mbfem/contact/de_saxce_method.h>
#include <mbfem/linear_algebra/convex_qp.h>

#include <deal.II/base/exceptions.h>

#include <ClpSimplex.hpp>
#include <CoinPackedMatrix.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace mbfem
{
  namespace
  {
    /** The cones and the floating blocks' equilibrium as Clp loads them. */
    struct ConeRows
    {
      std::vector<int>    row, column;
      std::vector<double> value;
      std::vector<double> row_lower, row_upper, column_lower, column_upper;

      void
      add_row(const std::vector<std::pair<int, double>> &entries,
              const double                               upper)
      {
        const int i = row_lower.size();
        for (const auto &[j, v] : entries)
          {
            row.push_back(i);
            column.push_back(j);
            value.push_back(v);
          }
        row_lower.push_back(-COIN_DBL_MAX);
        row_upper.push_back(upper);
      }
    };

    /**
     * Faces of the inscribed pyramid that stands for the 3D cone: 64, so
     * that it holds 0.9988 of the round cone's strength in every direction
     * (cos(pi / 64)); faces cost only rows of a pair's own block of the
     * QP's KKT matrix, not its size (Lemke's method, whose tableau grows
     * with them, takes 8).
     */
    constexpr unsigned int n_faces = 64;

    /**
     * The tangential section of the cone as a polygon inscribed in the
     * circle of radius c A + mu r_N, its corners on the directions
     * 2 pi j / 64 of the frame (the frame's axes among them): the unit normals
     * of its faces (tangential components 1 .. dim-1) and their distance
     * kappa from the centre, per unit radius. In 2D the two "faces" are
     * +-r_T = radius.
     */
    template <int dim>
    std::vector<Tensor<1, dim>>
    face_normals()
    {
      std::vector<Tensor<1, dim>> normals;
      if (dim == 2)
        for (const double sign : {1., -1.})
          {
            Tensor<1, dim> n;
            n[1] = sign;
            normals.push_back(n);
          }
      else
        for (unsigned int j = 0; j < n_faces; ++j)
          {
            const double   phi = 2. * M_PI * (j + 0.5) / n_faces;
            Tensor<1, dim> n;
            n[1]       = std::cos(phi);
            n[dim - 1] = std::sin(phi);
            normals.push_back(n);
          }
      return normals;
    }

    template <int dim>
    double
    face_distance()
    {
      return dim == 2 ? 1. : std::cos(M_PI / n_faces);
    }

    /**
     * The support function of the polygon per unit radius at @p v (the
     * largest product with a corner): the shift that makes the fixed
     * point's answer slip with u_N = 0 on the faceted cone (|u_T| in 2D
     * and for the round cone).
     */
    template <int dim>
    double
    support(const Tensor<1, dim> &v)
    {
      if (dim == 2)
        return std::abs(v[1]);
      double largest = 0.;
      for (unsigned int j = 0; j < n_faces; ++j)
        {
          const double phi = 2. * M_PI * j / n_faces;
          largest          = std::max(largest,
                             std::cos(phi) * v[1] + std::sin(phi) * v[dim - 1]);
        }
      return largest;
    }

    /**
     * The least normal force of the QPs (units of @p force_unit): minus the
     * tension limit, but not below the cone's apex -c A / mu, where the
     * convex part of the law ends; 0 without tension.
     */
    double
    normal_floor(const JointLaw &joint,
                 const double    area,
                 const bool      gone,
                 const double    force_unit)
    {
      const JointLaw::SlipLine line    = joint.slip_line(area, gone);
      const double             tension = joint.tensile_limit(area, gone);
      if (tension <= 0.)
        return 0.;
      return -(line.slope > 0. ?
                 std::min(tension, line.intercept / line.slope) :
                 tension) /
             force_unit;
    }

    /** Whether pair @p pair has friction rows (not tied, no tangent held). */
    template <int dim>
    bool
    has_cone(const typename ContactProblem<dim>::Pair &pair)
    {
      return !pair.tied && std::none_of(pair.held.begin() + 1,
                                        pair.held.end(),
                                        [](bool h) { return h; });
    }

    /**
     * Pair @p k's columns and cone rows, forces in units of @p force_unit:
     * r_N above the tension limit (or 0), the cone |r_T| <= c A + mu r_N
     * (faceted in 3D); a held direction carries nothing, a pair with a
     * held tangent no friction (as in Lemke's method), a tied pair's force
     * is free in its other directions (its optimality condition is u = 0).
     */
    template <int dim>
    void
    add_pair(const typename ContactProblem<dim>::Pair &pair,
             const unsigned int                        k,
             const bool                                gone,
             const double                              force_unit,
             ConeRows                                 &rows)
    {
      const unsigned int first = k * dim;
      for (unsigned int e = 0; e < dim; ++e)
        if (pair.held[e])
          rows.column_lower[first + e] = rows.column_upper[first + e] = 0.;
      if (pair.tied)
        return;
      const JointLaw::SlipLine line = pair.joint.slip_line(pair.area, gone);
      const double             mu   = line.slope;
      const double             c    = line.intercept / force_unit;
      if (!pair.held[0])
        rows.column_lower[first] =
          normal_floor(pair.joint, pair.area, gone, force_unit);
      if (!has_cone<dim>(pair))
        {
          for (unsigned int e = 1; e < dim; ++e)
            rows.column_lower[first + e] = rows.column_upper[first + e] = 0.;
          return;
        }
      const double kappa = face_distance<dim>();
      for (const Tensor<1, dim> &n : face_normals<dim>())
        {
          std::vector<std::pair<int, double>> entries{{first, -kappa * mu}};
          for (unsigned int e = 1; e < dim; ++e)
            entries.emplace_back(first + e, n[e]);
          rows.add_row(entries, kappa * c);
        }
    }

    /** The rows and columns of @p problem with the joints in @p broken. */
    template <int dim>
    ConeRows
    cone_rows(const ContactProblem<dim> &problem,
              const std::vector<bool>   &broken,
              const double               force_unit)
    {
      ConeRows           rows;
      const unsigned int n = problem.n_pairs * dim;
      rows.column_lower.assign(n, -COIN_DBL_MAX);
      rows.column_upper.assign(n, COIN_DBL_MAX);
      for (unsigned int k = 0; k < problem.n_pairs; ++k)
        add_pair<dim>(problem.pairs[k],
                      k,
                      problem.pairs[k].broken || broken[k],
                      force_unit,
                      rows);
      for (unsigned int a = 0; a < problem.n_alpha; ++a)
        {
          std::vector<std::pair<int, double>> entries;
          for (unsigned int i = 0; i < n; ++i)
            if (problem.G(i, a) != 0.)
              entries.emplace_back(i, problem.G(i, a));
          rows.add_row(entries, -problem.f[a] / force_unit);
          rows.row_lower.back() = rows.row_upper.back();
        }
      return rows;
    }

    /**
     * Whether forces in the cones of @p rows balance the floating blocks:
     * a phase-1 LP (Clp's dual simplex), each equilibrium row given two
     * slacks whose sum is minimised, as the statics certificate does, for
     * Clp's verdict of infeasibility is not to be trusted on these highly
     * degenerate LPs (a 3D incline with 64-sided cones was called
     * infeasible 0.1 % inside its limit). The rows' data are of order one,
     * so the LP asks for 1e-10 and calls a sum of slacks below 1e-8
     * feasible; an LP Clp does not solve counts as feasible (the QPs then
     * decide).
     */
    bool
    phase_one_feasible(ConeRows rows)
    {
      const unsigned int  n = rows.column_lower.size();
      std::vector<double> objective(n, 0.);
      for (unsigned int i = 0; i < rows.row_lower.size(); ++i)
        if (rows.row_lower[i] == rows.row_upper[i])
          for (const double sign : {1., -1.})
            {
              rows.row.push_back(i);
              rows.column.push_back(objective.size());
              rows.value.push_back(sign);
              rows.column_lower.push_back(0.);
              rows.column_upper.push_back(COIN_DBL_MAX);
              objective.push_back(1.);
            }
      const CoinPackedMatrix matrix(true,
                                    rows.row.data(),
                                    rows.column.data(),
                                    rows.value.data(),
                                    rows.value.size());
      for (const int scaling : {3, 0})
        {
          ClpSimplex model;
          model.setLogLevel(0);
          model.loadProblem(matrix,
                            rows.column_lower.data(),
                            rows.column_upper.data(),
                            objective.data(),
                            rows.row_lower.data(),
                            rows.row_upper.data());
          model.scaling(scaling);
          model.setPrimalTolerance(1e-10);
          model.setDualTolerance(1e-10);
          model.dual();
          if (model.isProvenOptimal())
            return model.objectiveValue() <= 1e-8;
        }
      return true;
    }

    /**
     * The QP's constraints from @p rows: the equalities (the floating
     * blocks' equilibrium first, then the columns fixed at zero) into A and
     * b, the cone rows and the columns' finite lower bounds into C x <= d.
     */
    ConvexQp
    as_qp(const ConeRows &rows)
    {
      using Entries = std::vector<std::pair<unsigned int, double>>;
      ConvexQp             qp;
      const unsigned int   n = rows.column_lower.size();
      std::vector<Entries> by_row(rows.row_lower.size());
      for (unsigned int e = 0; e < rows.value.size(); ++e)
        by_row[rows.row[e]].emplace_back(rows.column[e], rows.value[e]);
      std::vector<Entries> equal;
      std::vector<double>  right;
      for (unsigned int i = 0; i < by_row.size(); ++i)
        if (rows.row_lower[i] == rows.row_upper[i])
          {
            equal.push_back(by_row[i]);
            right.push_back(rows.row_upper[i]);
          }
        else
          qp.rows.push_back({by_row[i], rows.row_upper[i]});
      for (unsigned int j = 0; j < n; ++j)
        if (rows.column_lower[j] == rows.column_upper[j])
          {
            equal.push_back({{j, 1.}});
            right.push_back(rows.column_lower[j]);
          }
        else if (rows.column_lower[j] > -COIN_DBL_MAX)
          qp.rows.push_back({{{j, -1.}}, -rows.column_lower[j]});
      qp.A.reinit(equal.size(), n);
      qp.b.reinit(equal.size());
      for (unsigned int i = 0; i < equal.size(); ++i)
        {
          for (const auto &[j, v] : equal[i])
            qp.A(i, j) = v;
          qp.b(i) = right[i];
        }
      return qp;
    }
  } // namespace



  template <int dim>
  DeSaxceMethod<dim>::DeSaxceMethod(const ContactProblem<dim> &contact_problem,
                                    const unsigned int         max_qps,
                                    const double               relaxation)
    : problem(contact_problem)
    , max_qps(max_qps)
    , relaxation(relaxation)
    , broken(contact_problem.n_pairs, false)
  {
    Assert(problem.q.size() == problem.n_pairs * dim, ExcInternalError());
    Assert(problem.f.size() == problem.n_alpha, ExcInternalError());
    // Units in which the QP's data are of order one: the mean flexibility
    // s, forces F from the loads, the strengths and the gaps over s.
    double s = 0.;
    for (unsigned int i = 0; i < problem.n_pairs * dim; ++i)
      {
        const auto w = problem.W.find({i, i});
        s += (w == problem.W.end() ? 0. : std::abs(w->second));
      }
    s            = std::max(s / std::max(1u, problem.n_pairs * dim), 1e-300);
    double force = 0.;
    for (const double f : problem.f)
      force = std::max(force, std::abs(f));
    for (const double q : problem.q)
      force = std::max(force, std::abs(q) / s);
    for (const auto &pair : problem.pairs)
      force = std::max(force, pair.joint.shear_strength(0., pair.area, false));
    force_unit        = std::max(force, 1e-300);
    displacement_unit = force_unit * s;
  }



  template <int dim>
  bool
  DeSaxceMethod<dim>::solve_qp(const std::vector<double> &shift)
  {
    const unsigned int n     = problem.n_pairs * dim;
    const double       scale = displacement_unit / force_unit; // W's unit
    ConvexQp           qp    = as_qp(cone_rows(problem, broken, force_unit));
    qp.c.reinit(n);
    for (unsigned int i = 0; i < n; ++i)
      qp.c(i) = problem.q[i] / displacement_unit;
    for (unsigned int k = 0; k < problem.n_pairs; ++k)
      if (has_cone<dim>(problem.pairs[k]))
        qp.c(k * dim) +=
          problem.pairs[k].joint.slip_line(problem.pairs[k].area, true).slope *
          shift[k];
    qp.H.reinit(n, n);
    for (const auto &[index, w] : problem.W)
      qp.H(index.first, index.second) = w / scale;
    const ConvexQp::Status status = qp.solve(1e-10);
    if (status != ConvexQp::Status::optimal)
      {
        why = (status == ConvexQp::Status::infeasible ?
                 "found a QP whose multipliers diverged (unbounded where "
                 "the blocks' flexibility is singular)" :
                 "did not solve a QP in " + std::to_string(qp.iterations) +
                   " interior-point iterations");
        return false;
      }
    // The first rows of A are the floating blocks' equilibrium: their
    // multipliers are alpha in u = W r + q + G alpha.
    r = qp.x;
    alpha.reinit(problem.n_alpha);
    for (unsigned int a = 0; a < problem.n_alpha; ++a)
      alpha(a) = qp.y(a);
    u.reinit(n);
    for (unsigned int i = 0; i < n; ++i)
      u(i) = problem.q[i] / displacement_unit;
    for (const auto &[index, w] : problem.W)
      u(index.first) += w / scale * r(index.second);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int a = 0; a < problem.n_alpha; ++a)
        u(i) += problem.G(i, a) * alpha(a);
    return true;
  }



  template <int dim>
  bool
  DeSaxceMethod<dim>::statics_admits() const
  {
    return phase_one_feasible(cone_rows(problem, broken, force_unit));
  }



  template <int dim>
  bool
  DeSaxceMethod<dim>::fixed_point(unsigned int &qps, const unsigned int max)
  {
    std::vector<double> shift(problem.n_pairs, 0.);
    double              change = std::numeric_limits<double>::infinity();
    while (qps < max)
      {
        if (!solve_qp(shift))
          return false;
        ++qps;
        const double scale =
          std::max(u.size() > 0 ? u.linfty_norm() : 0., 1e-300);
        change = 0.;
        for (unsigned int k = 0; k < problem.n_pairs; ++k)
          {
            Tensor<1, dim> slip;
            for (unsigned int e = 1; e < dim; ++e)
              slip[e] = u(k * dim + e);
            const double next =
              (1. - relaxation) * shift[k] + relaxation * support<dim>(slip);
            change   = std::max(change, std::abs(next - shift[k]) / scale);
            shift[k] = next;
          }
        // The QPs' answers are good to about 1e-10 of their scales, 1e-7
        // where round-off ends the interior-point method (ConvexQp).
        if (change < 1e-7)
          return true;
      }
    std::ostringstream text;
    text << "did not settle in " << max
         << " QPs ('Contact/De Saxce/Maximum QPs'; the shifts still changed "
            "by "
         << std::scientific << std::setprecision(2) << change
         << " of the largest displacement)";
    why = text.str();
    return false;
  }



  template <int dim>
  bool
  DeSaxceMethod<dim>::solve(unsigned int &qps)
  {
    const unsigned int max = qps + max_qps;
    for (unsigned int pass = 0; pass <= problem.n_pairs; ++pass)
      {
        if (!statics_admits())
          {
            statics_failed_after_breaking = pass > 0;
            why = "found that statics admits no forces in the cones its "
                  "QPs use (" +
                  std::string(dim == 3 ? "faceted, inside the round ones" :
                                         "the law's, or a convex part of it "
                                         "where joints carry tension") +
                  ")" +
                  std::string(pass > 0 ? " once the joints that opened "
                                         "had lost their strength" :
                                         "");
            return false;
          }
        if (!fixed_point(qps, max))
          return false;
        const std::vector<unsigned int> opened = newly_open();
        if (opened.empty())
          return true;
        for (const unsigned int k : opened)
          broken[k] = true;
      }
    why = "broke every joint and did not settle";
    return false;
  }



  template <int dim>
  std::vector<unsigned int>
  DeSaxceMethod<dim>::newly_open() const
  {
    const double gap = answer_tolerance * (u.size() > 0 ? u.linfty_norm() : 0.);
    std::vector<unsigned int> opened;
    for (unsigned int k = 0; k < problem.n_pairs; ++k)
      {
        const auto &pair = problem.pairs[k];
        if (!pair.tied && !pair.held[0] && u(k * dim) > gap &&
            !(pair.broken || broken[k]) && pair.joint.has_strength())
          opened.push_back(k);
      }
    return opened;
  }



  template <int dim>
  std::string
  DeSaxceMethod<dim>::failure() const
  {
    return why;
  }



  template <int dim>
  bool
  DeSaxceMethod<dim>::stopped_after_breaking() const
  {
    return statics_failed_after_breaking;
  }



  template <int dim>
  std::vector<bool>
  DeSaxceMethod<dim>::broken_flags(const std::vector<bool> &committed) const
  {
    std::vector<bool> flags = committed;
    for (unsigned int k = 0; k < broken.size() && k < flags.size(); ++k)
      flags[k] = flags[k] || broken[k];
    return flags;
  }



  template <int dim>
  StateTrial<dim>
  DeSaxceMethod<dim>::answer_states(const StateTrial<dim> &committed) const
  {
    // An interior-point answer satisfies each complementarity only to its
    // tolerance: of the two members (gap and normal force; slip and the
    // cone's room) the relatively larger one decides.
    const double u_max = std::max(u.size() > 0 ? u.linfty_norm() : 0., 1e-300);
    const double r_max = std::max(r.size() > 0 ? r.linfty_norm() : 0., 1e-300);
    StateTrial<dim> trial = committed;
    for (unsigned int k = 0; k < problem.n_pairs; ++k)
      {
        const auto &pair = problem.pairs[k];
        if (pair.tied)
          continue;
        trial.tensile_slip[k]        = false;
        trial.direction_stiffness[k] = 0.;
        trial.broken[k]              = trial.broken[k] || broken[k];
        const bool   gone            = pair.broken || trial.broken[k];
        const double r_n             = r(k * dim) * force_unit;
        const double floor =
          normal_floor(pair.joint, pair.area, gone, force_unit);
        if (!pair.held[0] && u(k * dim) / u_max > (r(k * dim) - floor) / r_max)
          {
            trial.state[k] = ContactState::open;
            continue;
          }
        Tensor<1, dim> slip, shear;
        for (unsigned int e = 1; e < dim; ++e)
          {
            slip[e]  = u(k * dim + e);
            shear[e] = r(k * dim + e);
          }
        if (!has_cone<dim>(pair) || slip.norm() == 0.)
          {
            trial.state[k] = ContactState::stick;
            continue;
          }
        // The room left to the QP's cone (faceted in 3D).
        const JointLaw::SlipLine line = pair.joint.slip_line(pair.area, gone);
        double                   room = face_distance<dim>() *
                      (line.intercept / force_unit + line.slope * r(k * dim));
        double largest = 0.;
        for (const Tensor<1, dim> &n : face_normals<dim>())
          largest = std::max(largest, n * shear);
        room = std::max(room - largest, 0.);
        if (slip.norm() / u_max <= room / r_max)
          {
            trial.state[k] = ContactState::stick;
            continue;
          }
        const double strength = pair.joint.shear_strength(r_n, pair.area, gone);
        trial.state[k]        = ContactState::slip;
        trial.slip_direction[k] = slip / slip.norm();
        trial.tensile_slip[k]   = r_n < -answer_tolerance * r_max * force_unit;
        trial.direction_stiffness[k] =
          (dim == 3 ? strength / slip.norm() / displacement_unit : 0.);
      }
    return trial;
  }



  template class DeSaxceMethod<2>;
  template class DeSaxceMethod<3>;
} // namespace mbfem
