#include <mbfem/linear_algebra/convex_qp.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <cmath>
#include <exception>

namespace mbfem
{
  namespace
  {
    /** The largest step in (0, 1] that keeps v + t dv >= 0. */
    double
    step_to_boundary(const Vector<double> &v, const Vector<double> &dv)
    {
      double t = 1.;
      for (unsigned int i = 0; i < v.size(); ++i)
        if (dv(i) < 0.)
          t = std::min(t, -v(i) / dv(i));
      return t;
    }

    /** |v|_inf, 0 for an empty vector (which deal.II's norm refuses). */
    double
    largest(const Vector<double> &v)
    {
      return v.size() > 0 ? v.linfty_norm() : 0.;
    }

    /** v += t w, nothing for empty vectors (deal.II's add() refuses them:
     * a QP without equalities or without inequalities). */
    void
    add(Vector<double> &v, const double t, const Vector<double> &w)
    {
      if (v.size() > 0)
        v.add(t, w);
    }
  } // namespace



  void
  ConvexQp::multiply_rows(const Vector<double> &v, Vector<double> &out) const
  {
    out.reinit(rows.size());
    for (unsigned int i = 0; i < rows.size(); ++i)
      for (const auto &[j, a] : rows[i].entries)
        out(i) += a * v(j);
  }



  void
  ConvexQp::multiply_rows_transposed(const Vector<double> &w,
                                     Vector<double>       &out) const
  {
    out.reinit(c.size());
    for (unsigned int i = 0; i < rows.size(); ++i)
      for (const auto &[j, a] : rows[i].entries)
        out(j) += a * w(i);
  }



  void
  ConvexQp::residuals(const Vector<double> &s, Residuals &r) const
  {
    // H x + c + A^T y + C^T z, A x - b, C x + s - d.
    Vector<double> tmp;
    r.dual.reinit(c.size());
    H.vmult(r.dual, x);
    r.dual += c;
    // (Without equalities A is 0 x 0: deal.II's tables drop every
    // dimension where one is zero.)
    if (b.size() > 0)
      A.Tvmult_add(r.dual, y);
    multiply_rows_transposed(z, tmp);
    r.dual += tmp;
    r.equality.reinit(b.size());
    if (b.size() > 0)
      {
        A.vmult(r.equality, x);
        r.equality -= b;
      }
    multiply_rows(x, r.inequality);
    add(r.inequality, 1., s);
    for (unsigned int i = 0; i < rows.size(); ++i)
      r.inequality(i) -= rows[i].bound;
  }



  bool
  ConvexQp::factorise(const Vector<double>     &s,
                      LAPACKFullMatrix<double> &K) const
  {
    // The reduced KKT matrix [H + C^T D C, A^T; A, 0], D = Z S^-1, a
    // little of H's diagonal added where H is singular on free columns.
    const unsigned int n = c.size(), m = b.size();
    K.reinit(n + m, n + m);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        K(i, j) = H(i, j);
    for (unsigned int i = 0; i < n; ++i)
      K(i, i) += 1e-14 * (1. + std::abs(H(i, i)));
    for (unsigned int k = 0; k < rows.size(); ++k)
      {
        const double dk = z(k) / s(k);
        for (const auto &[i, a] : rows[k].entries)
          for (const auto &[j, e] : rows[k].entries)
            K(i, j) += dk * a * e;
      }
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int j = 0; j < n; ++j)
        {
          K(n + i, j) = A(i, j);
          K(j, n + i) = A(i, j);
        }
    try
      {
        K.compute_lu_factorization();
      }
    catch (const std::exception &)
      {
        // An equilibrium row without entries, dependent equalities.
        return false;
      }
    return true;
  }



  void
  ConvexQp::newton_step(const LAPACKFullMatrix<double> &K,
                        const Vector<double>           &s,
                        const Residuals                &r,
                        const Vector<double>           &r_c,
                        Step                           &step) const
  {
    // S dz + Z ds = r_c and C dx + ds = -r_in eliminated:
    // (H + C^T D C) dx + A^T dy = -r_dual - C^T (Z r_in + r_c) / S.
    const unsigned int n = c.size(), m = b.size(), p = rows.size();
    Vector<double>     w(p), rhs(n + m), ct(n), Cdx;
    for (unsigned int k = 0; k < p; ++k)
      w(k) = (z(k) * r.inequality(k) + r_c(k)) / s(k);
    multiply_rows_transposed(w, ct);
    for (unsigned int i = 0; i < n; ++i)
      rhs(i) = -r.dual(i) - ct(i);
    for (unsigned int i = 0; i < m; ++i)
      rhs(n + i) = -r.equality(i);
    K.solve(rhs);
    step.x.reinit(n);
    step.y.reinit(m);
    for (unsigned int i = 0; i < n; ++i)
      step.x(i) = rhs(i);
    for (unsigned int i = 0; i < m; ++i)
      step.y(i) = rhs(n + i);
    multiply_rows(step.x, Cdx);
    step.z.reinit(p);
    step.s.reinit(p);
    for (unsigned int k = 0; k < p; ++k)
      {
        step.z(k) = (z(k) * (Cdx(k) + r.inequality(k)) + r_c(k)) / s(k);
        step.s(k) = (r_c(k) - s(k) * step.z(k)) / z(k);
      }
  }



  ConvexQp::Status
  ConvexQp::solve(const double tolerance, const unsigned int max_iterations)
  {
    const unsigned int p = rows.size();
    x.reinit(c.size());
    y.reinit(b.size());
    z.reinit(p);
    Vector<double> s(p), r_c(p);
    double         largest_bound = 0.;
    for (unsigned int i = 0; i < p; ++i)
      {
        s(i)          = std::max(rows[i].bound, 1.);
        z(i)          = 1.;
        largest_bound = std::max(largest_bound, std::abs(rows[i].bound));
      }
    const double scale_c = 1. + largest(c), scale_b = 1. + largest(b),
                 scale_d = 1. + largest_bound;
    Residuals                r;
    LAPACKFullMatrix<double> K;
    Step                     step;
    for (iterations = 0; iterations < max_iterations; ++iterations)
      {
        residuals(s, r);
        const double mu   = (p > 0 ? (s * z) / p : 0.);
        const double fits = std::max({largest(r.dual) / scale_c,
                                      largest(r.equality) / scale_b,
                                      largest(r.inequality) / scale_d});
        if (fits < tolerance && mu < tolerance * scale_c * scale_d)
          return Status::optimal;
        // Past the round-off of the KKT solves the residuals grow again
        // as mu falls: stop there at residuals within 1e3 times the
        // tolerance.
        if (mu < 1e-3 * tolerance * tolerance * scale_c * scale_d &&
            fits < 1e3 * tolerance)
          return Status::optimal;
        // Infeasibility or unboundedness shows as z growing without bound.
        if (largest(z) > 1e14 * scale_c)
          return Status::infeasible;
        if (!factorise(s, K))
          return Status::stalled;

        // Mehrotra's predictor, then the corrector with its centring.
        for (unsigned int k = 0; k < p; ++k)
          r_c(k) = -s(k) * z(k);
        newton_step(K, s, r, r_c, step);
        const double t_aff =
          std::min(step_to_boundary(s, step.s), step_to_boundary(z, step.z));
        double mu_aff = 0.;
        for (unsigned int k = 0; k < p; ++k)
          mu_aff += (s(k) + t_aff * step.s(k)) * (z(k) + t_aff * step.z(k));
        mu_aff /= std::max(p, 1u);
        const double sigma = (mu > 0. ? std::pow(mu_aff / mu, 3) : 0.);
        for (unsigned int k = 0; k < p; ++k)
          r_c(k) = -s(k) * z(k) - step.s(k) * step.z(k) + sigma * mu;
        newton_step(K, s, r, r_c, step);
        const double t = 0.99 * std::min(step_to_boundary(s, step.s),
                                         step_to_boundary(z, step.z));
        add(x, t, step.x);
        add(y, t, step.y);
        add(z, t, step.z);
        add(s, t, step.s);
      }
    return Status::stalled;
  }
} // namespace mbfem
