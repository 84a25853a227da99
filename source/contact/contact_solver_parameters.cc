#include <mbfem/contact/contact_solver_parameters.h>

namespace mbfem
{
  void
  ContactSolverParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    {
      prm.declare_entry(
        "Maximum iterations",
        "100",
        Patterns::Integer(1),
        "Most iterations of the fast contact-state iteration (assume "
        "states, solve, check, switch) in one load increment. Where it does "
        "not settle in as many (or cycles, or meets a singular trial), the "
        "load path concludes the increment (condensed formulation; "
        "doc/state_iteration.md); with the monolithic formulation the run "
        "stops with a message. The methods that follow have limits of their "
        "own, which this one does not bound: the load path at most 20 "
        "switches per pair plus 100 (each switch changes one pair's state "
        "at the load where its condition is reached, so stopping early "
        "would leave the increment unsolved rather than solved worse), the "
        "semismooth Newton method 'Semismooth Newton/Maximum iterations'. "
        "The screen line and the summary CSV count each method's "
        "iterations apart.");
      prm.declare_entry(
        "Formulation",
        "condensed",
        Patterns::Selection("condensed|monolithic|both"),
        "How the interface system is solved. condensed: the multi-body "
        "method, each block's flexibility at its contact DoFs from unit "
        "loads, the contact iteration on the pairs' forces and the floating "
        "blocks' rigid-body amplitudes only. monolithic: the reference, all "
        "blocks' displacements and the pairs' forces (Lagrange multipliers) "
        "in one sparse system, factorised at every state iteration, with the "
        "same stick/slip/open logic. both: the condensed solve gives the "
        "results, the monolithic one runs beside it from the same load "
        "increments; their pair states, forces (relative to the largest pair "
        "force), gaps and slips (relative to the largest displacement) are "
        "compared at every increment, and both are timed.");
      prm.declare_entry(
        "State system",
        "auto",
        Patterns::Selection("auto|dense|sparse"),
        "How the condensed formulation factorises the system of each state "
        "trial (the forces of the pairs that are not open and the floating "
        "blocks' rigid-body amplitudes). dense: LU by LAPACK. sparse: LU by "
        "UMFPACK, with an entry only where two pairs share a block, which "
        "pays when many blocks each touch a few neighbours (walls, jointed "
        "rock). auto: sparse when the system has at least 1000 unknowns "
        "and at most a tenth of its entries can be non-zero, else dense. "
        "(The semismooth Newton method factorises its Jacobian sparse "
        "always.)");
      prm.declare_entry(
        "Flexibility columns",
        "auto",
        Patterns::Selection("auto|whole|on demand"),
        "How the condensed formulation computes each block's flexibility "
        "(its displacements at the contact DoFs under unit loads there). "
        "whole: every column at the start. on demand: the block's "
        "factorisation is kept and a pair's columns are computed when it "
        "first closes, so that time and memory grow with the pairs that "
        "carry force, not with all; a stuck pair with no gap, no force yet "
        "and no strength, between blocks that cannot move rigidly, then "
        "starts the iteration open, and there a trial closes only the open "
        "pairs penetrating at least 0.9 times as deep as the deepest. A "
        "block with a plastic tangent is "
        "always whole. auto: on demand for blocks with at least 500 "
        "contact DoFs, else whole.");
      StateMethodParameters::declare_parameters(prm);
    }
    prm.leave_subsection();
  }



  void
  ContactSolverParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    {
      max_iterations           = prm.get_integer("Maximum iterations");
      const std::string choice = prm.get("Formulation");
      formulation = (choice == "monolithic" ? Formulation::monolithic :
                     choice == "both"       ? Formulation::both :
                                              Formulation::condensed);
      state_method.parse_parameters(prm);
      const std::string system  = prm.get("State system");
      state_system              = (system == "dense"  ? StateSystem::dense :
                                   system == "sparse" ? StateSystem::sparse :
                                                        StateSystem::automatic);
      const std::string columns = prm.get("Flexibility columns");
      flexibility_columns =
        (columns == "whole"     ? FlexibilityColumns::whole :
         columns == "on demand" ? FlexibilityColumns::on_demand :
                                  FlexibilityColumns::automatic);
    }
    prm.leave_subsection();
  }
} // namespace mbfem
