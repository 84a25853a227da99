// What a state method sees of an increment (IncrementContext): the
// ContactSolver's data of the increment, and the services the methods
// share (the polishing of another method's states, the refusal of answers
// that leave a mechanism, the load fraction).

#include <mbfem/contact/increment_context.h>

#include <algorithm>

namespace mbfem
{
  template <int dim>
  IncrementContext<dim>::IncrementContext(ContactSolver<dim> &solver,
                                          const unsigned int  increment,
                                          const bool          from_last_solve,
                                          const bool          followed)
    : increment(increment)
    , from_last_solve(from_last_solve)
    , followed(followed)
    , solver(solver)
  {}



  template <int dim>
  std::string
  IncrementContext<dim>::head() const
  {
    return "Load increment " + std::to_string(increment);
  }



  template <int dim>
  std::string
  IncrementContext<dim>::method_failure(const std::string &method,
                                        const std::string &why) const
  {
    return head() + ": " + method + " " + why +
           (!why.empty() && why.back() == '.' ? "" : ".");
  }



  template <int dim>
  const StateMethodParameters &
  IncrementContext<dim>::parameters() const
  {
    return solver.method_parameters;
  }



  template <int dim>
  bool
  IncrementContext<dim>::monolithic() const
  {
    return solver.monolithic != nullptr;
  }



  template <int dim>
  const std::vector<ContactPair<dim>> &
  IncrementContext<dim>::pairs() const
  {
    return solver.contact_pairs;
  }



  template <int dim>
  CondensedSystem<dim> &
  IncrementContext<dim>::condensed() const
  {
    AssertThrow(solver.condensed != nullptr, ExcInternalError());
    return *solver.condensed;
  }



  template <int dim>
  const RigidCoupling<dim> &
  IncrementContext<dim>::coupling() const
  {
    return solver.coupling;
  }



  template <int dim>
  const std::vector<std::array<bool, dim>> &
  IncrementContext<dim>::held() const
  {
    return solver.held;
  }



  template <int dim>
  IncrementLoads &
  IncrementContext<dim>::loads() const
  {
    return solver.loads;
  }



  template <int dim>
  const IncrementLoads &
  IncrementContext<dim>::full_loads() const
  {
    return solver.full_loads;
  }



  template <int dim>
  const IncrementLoads &
  IncrementContext<dim>::start_loads() const
  {
    return solver.start_loads;
  }



  template <int dim>
  const StateCheck<dim> &
  IncrementContext<dim>::state_check() const
  {
    return *solver.state_check;
  }



  template <int dim>
  const MechanismTest<dim> &
  IncrementContext<dim>::mechanisms() const
  {
    return solver.mechanisms;
  }



  template <int dim>
  const StateTrial<dim> &
  IncrementContext<dim>::committed() const
  {
    return solver.committed;
  }



  template <int dim>
  const Vector<double> &
  IncrementContext<dim>::committed_solution() const
  {
    return solver.committed_solution;
  }



  template <int dim>
  const std::vector<Tensor<1, dim>> &
  IncrementContext<dim>::committed_displacement() const
  {
    return solver.committed_displacement;
  }



  template <int dim>
  bool
  IncrementContext<dim>::committed_solved() const
  {
    return solver.committed_solved;
  }



  template <int dim>
  const StateTrial<dim> &
  IncrementContext<dim>::current() const
  {
    return solver.current;
  }



  template <int dim>
  StateTrial<dim>
  IncrementContext<dim>::committed_open_on_demand() const
  {
    return solver.state_check->open_on_demand(solver.committed,
                                              solver.committed_solution);
  }



  template <int dim>
  typename FastIteration<dim>::Outcome
  IncrementContext<dim>::fast_iteration(const Trial       &trial,
                                        const unsigned int stall_iterations)
  {
    return solver.fast_iteration(trial, increment, stall_iterations);
  }



  template <int dim>
  typename FastIteration<dim>::Solve
  IncrementContext<dim>::trial_solve()
  {
    return solver.trial_solve();
  }



  template <int dim>
  void
  IncrementContext<dim>::settle(const Trial        &states,
                                StateMethodOutcome &outcome)
  {
    const auto polish = fast_iteration(states);
    outcome.iterations += polish.iterations;
    if (!polish.converged)
      {
        outcome.failure = "found an answer, but its states did not settle "
                          "in the fast iteration that checks them";
        return;
      }
    const std::string moving = refused_mechanism();
    if (!moving.empty())
      {
        outcome.failure = "found an answer, but it was refused: its states "
                          "leave a mechanism:" +
                          moving;
        return;
      }
    outcome.converged = true;
  }



  template <int dim>
  std::string
  IncrementContext<dim>::refused_mechanism() const
  {
    // In 3D a block can be in equilibrium with every pair slipping below
    // its limit: the slip directions, spread by the block's elastic
    // deformation, hold it. MechanismTest ignores that (it counts a slipping
    // pair as no resistance), so such states name a mechanism. The answer
    // stands if its slip is of the order of the blocks' deformation: the
    // fast iteration's check has verified the forces within every pair's
    // strength and the equilibrium is solved, so it is statically
    // admissible; what is refused is the unbounded slip (1e7 m on issue
    // 20's wedge) with which a linearised direction can make such states
    // regular beyond a limit.
    const std::string moving = solver.mechanisms.describe(solver.current);
    if (moving.empty() || (dim == 3 && slip_is_elastic()))
      return "";
    return moving;
  }



  namespace
  {
    /**
     * A 3D answer with every pair of a block slipping stands if its largest
     * slip increment is below this times the largest elastic relative
     * displacement (0.63 and 1.35 on the 3D incline at 0.999 of its limit,
     * in 10 increments and in one); the unbounded slips it refuses beyond
     * a limit are orders of magnitude larger (|u| of 1e7 m on issue 20's
     * wedge).
     */
    constexpr double elastic_slip_factor = 1e3;
  } // namespace



  template <int dim>
  bool
  IncrementContext<dim>::slip_is_elastic() const
  {
    // The deformation part of d: Delta_F + C_hat rho, without the rigid
    // motions P_hat alpha.
    const unsigned int n_pairs = solver.n_pairs;
    Vector<double>     forces(solver.current_solution);
    for (unsigned int a = 0; a < solver.coupling.n_modes(); ++a)
      forces(n_pairs * dim + a) = 0.;
    const double elastic =
      condensed().relative_displacement(forces, solver.loads).linfty_norm();
    double slip = 0.;
    for (unsigned int k = 0; k < n_pairs; ++k)
      if (solver.current.state[k] == ContactState::slip)
        slip = std::max(slip, solver.slip_increment(k).norm());
    return slip <= elastic_slip_factor * elastic;
  }



  template <int dim>
  void
  IncrementContext<dim>::set_path_start()
  {
    // The start: the load for which the committed solution is exact with
    // the present C_hat, P_hat (these change between Newton's passes).
    const unsigned int n_r         = solver.n_pairs * dim;
    IncrementLoads    &loads       = solver.loads;
    solver.full_loads.displacement = loads.displacement;
    solver.full_loads.resultant    = loads.resultant;
    Vector<double> start(n_r + solver.coupling.n_modes());
    if (solver.committed_solution.size() == start.size())
      start = solver.committed_solution;
    loads.displacement.reinit(n_r);
    IncrementLoads &start_loads = solver.start_loads;
    start_loads.displacement = condensed().relative_displacement(start, loads);
    start_loads.displacement *= -1.;
    for (unsigned int k = 0; k < solver.n_pairs; ++k)
      for (unsigned int i = 0; i < dim; ++i)
        start_loads.displacement(k * dim + i) +=
          solver.committed_displacement[k][i];
    start_loads.resultant.assign(solver.coupling.n_modes(), 0.);
    for (unsigned int j = 0; j < n_r; ++j)
      for (const auto &[a, value] : solver.coupling.row(j))
        start_loads.resultant[a] -= value * start(j);
  }



  template <int dim>
  void
  IncrementContext<dim>::set_load_fraction(const double s)
  {
    solver.loads.set_fraction(solver.start_loads, solver.full_loads, s);
  }



  template <int dim>
  ContactProblem<dim>
  IncrementContext<dim>::problem(const bool with_flexibility) const
  {
    return solver.condensed_problem(increment, 0., false, with_flexibility);
  }



  template <int dim>
  IncrementContext<dim>::StatesGuard::StatesGuard(
    IncrementContext<dim> &context)
    : solver(context.solver)
    , trial(solver.current)
    , solution(solver.current_solution)
    , displacement(solver.current_displacement)
  {}



  template <int dim>
  IncrementContext<dim>::StatesGuard::~StatesGuard()
  {
    if (kept)
      return;
    solver.current              = trial;
    solver.current_solution     = solution;
    solver.current_displacement = displacement;
  }



  template <int dim>
  void
  IncrementContext<dim>::StatesGuard::keep()
  {
    kept = true;
  }



  template class IncrementContext<2>;
  template class IncrementContext<3>;
} // namespace mbfem
