#include <mbfem/contact/contact_state.h>
#include <mbfem/contact/state_method.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <algorithm>

namespace mbfem
{
  namespace
  {
    /** The registry's names (the same in 2D and 3D: one list). */
    std::vector<std::string>
    all_names()
    {
      std::vector<std::string> names;
      for (const auto &entry : registered_state_methods<2>())
        names.push_back(entry.name);
      return names;
    }
  } // namespace



  std::string
  state_method_names()
  {
    std::string names;
    for (const std::string &name : all_names())
      names += (names.empty() ? "" : "|") + name;
    return names;
  }



  std::vector<std::string>
  parse_state_methods(const std::string &text)
  {
    const std::vector<std::string> known = all_names();
    std::vector<std::string>       methods;
    for (const std::string &name : dealii::Utilities::split_string_list(text))
      {
        AssertThrow(std::find(known.begin(), known.end(), name) != known.end(),
                    dealii::ExcMessage("Contact/State method: '" + name +
                                       "' is not a method; the methods are " +
                                       state_method_names() + "."));
        AssertThrow(std::find(methods.begin(), methods.end(), name) ==
                      methods.end(),
                    dealii::ExcMessage("Contact/State method: '" + name +
                                       "' is listed twice."));
        methods.push_back(name);
      }
    AssertThrow(!methods.empty(),
                dealii::ExcMessage(
                  "Contact/State method: name at least one method."));
    return methods;
  }



  std::string
  join_state_methods(const std::vector<std::string> &methods)
  {
    std::string text;
    for (const std::string &method : methods)
      text += (text.empty() ? "" : ", ") + method;
    return text;
  }



  namespace
  {
    /** "fast: assume states, ... load continuation: ...", from the registry. */
    std::string
    method_descriptions()
    {
      std::string text;
      for (const auto &entry : registered_state_methods<2>())
        text += entry.name + ": " + entry.description + " ";
      return text;
    }
  } // namespace



  namespace
  {
    using namespace dealii;

    /** The methods of an increment and their order. */
    void
    declare_order_entries(ParameterHandler &prm)
    {
      prm.declare_entry(
        "State method",
        join_state_methods(all_names()),
        Patterns::List(Patterns::Selection(state_method_names()),
                       1,
                       all_names().size()),
        "The methods of each increment's state iteration, tried in this "
        "order until one concludes (but see 'Method order'; "
        "doc/state_iteration.md). " +
          method_descriptions() +
          "The "
          "monolithic formulation runs the fast iteration only. "
          "Where none concludes, the verdict is that of the fast iteration "
          "or the load path (no equilibrium if one met it). The order "
          "matters where an increment has more than one solution: each "
          "method may find another (doc/state_iteration.md).");
      prm.declare_entry(
        "Fast iteration stall",
        "10",
        Patterns::Integer(0),
        "Where another method follows the fast iteration in the increment's "
        "order ('State method', 'Method order'), the fast iteration gives way to it once the number of pairs that "
        "switch state has not fallen to a new low in this many solves "
        "(while it switches every failing pair, before a cycle makes it "
        "switch one at a time): it then wanders, each solve a full one (on "
        "the 125-block cube 100 solves, 60 s, before the next method "
        "concluded). 0: never; it ends where it converges, at 'Maximum "
        "iterations', at a singular trial or where it cycles switching one "
        "pair at a time.");
      prm.declare_entry(
        "Method order",
        "last concluded first",
        Patterns::Selection("as listed|last concluded first"),
        "as listed: every increment tries the methods of 'State method' in "
        "their order. last concluded first: where the load path or the "
        "semismooth Newton method concluded the last increment, the next "
        "starts with it, the others following in their order, so that a "
        "model whose increments the fast iteration does not conclude pays "
        "for its trials once, not at every increment (doc/state_iteration.md; "
        "Lemke's method and the load continuation are not moved: their work "
        "does not shrink with the increment's). A run's first increment, a "
        "stage's that changes the contact set-up (an excavation), each "
        "trial of a strength reduction and the plastic Newton method's passes "
        "after an increment's first (whose fast iteration starts from the "
        "last pass's states) start as listed. Where an increment has more "
        "than one solution the order decides which is found.");
    }

    /** Contact/Semismooth Newton. */
    void
    declare_newton_entries(ParameterHandler &prm)
    {
      prm.enter_subsection("Semismooth Newton");
      {
        prm.declare_entry("Maximum iterations",
                          "200",
                          Patterns::Integer(1),
                          "Newton iterations per system (the system is solved "
                          "again each time a joint breaks) before the method "
                          "gives up on the increment.");
        prm.declare_entry(
          "Tolerance",
          "1e-11",
          Patterns::Double(1e-15, state_tolerance),
          "Newton has converged where every residual is below this times the "
          "largest force or displacement of the increment's data. At most "
          "1e-9, the state check's tolerance, so that the states read from "
          "Newton's answer are those the check accepts.");
        prm.declare_entry(
          "Proximal stiffness",
          "1e-4",
          Patterns::Double(0.),
          "Where Newton's method stalls or meets a singular Jacobian (mostly "
          "a floating block that no closed pair holds), it starts again with "
          "every "
          "floating block held by a spring to where it was, this stiff "
          "relative to a contact, and moves the springs' anchors to the "
          "blocks after each solve (a proximal point iteration on the rigid "
          "motions) until the springs carry nothing; then Newton's method "
          "without springs concludes; where the springs fail after a "
          "singular Jacobian, Newton's method runs once more with "
          "Levenberg-Marquardt's steps past it. 0: no springs.");
        prm.declare_entry("Proximal steps",
                          "100",
                          Patterns::Integer(1),
                          "How often the springs' anchors may move before the "
                          "second try gives up.");
      }
      prm.leave_subsection();
    }

    /** Contact/Lemke. */
    void
    declare_lemke_entries(ParameterHandler &prm)
    {
      prm.enter_subsection("Lemke");
      {
        prm.declare_entry(
          "Maximum variables",
          "2000",
          Patterns::Integer(1),
          "Lemke's method is not tried on an increment whose problem has more "
          "variables than this (in 2D 4 or 5 per pair and 2 per floating "
          "mode; in 3D 10 or 11 per pair): its tableau is dense, 16 n^2 bytes "
          "(64 MB at 2000), and a pivot costs 2 n^2 operations.");
        prm.declare_entry(
          "Pivots per variable",
          "10",
          Patterns::Integer(1),
          "Lemke's method gives up after this many pivots per variable of the "
          "problem (it needed 0.5 to 0.8 on the problems of "
          "doc/state_iteration.md).");
      }
      prm.leave_subsection();
    }

    /** Contact/De Saxce. */
    void
    declare_de_saxce_entries(ParameterHandler &prm)
    {
      prm.enter_subsection("De Saxce");
      {
        prm.declare_entry(
          "Maximum QPs",
          "200",
          Patterns::Integer(1),
          "De Saxce's fixed point gives up after this many convex QPs on one "
          "increment (it took 30 to 62 on the problems of "
          "doc/state_iteration.md).");
        prm.declare_entry(
          "Maximum pairs",
          "500",
          Patterns::Integer(1),
          "De Saxce's fixed point is not tried on an increment of more pairs: "
          "its QPs are dense, each interior-point step an LU of about dim "
          "times the pairs unknowns (173 pairs in 2D: 38 QPs in 0.9 s; the "
          "time grows with the cube of the pairs).");
        prm.declare_entry(
          "Relaxation",
          "0.5",
          Patterns::Double(0.01, 1.),
          "The shift of each pair's gap moves this fraction of the way to "
          "its slip at each QP (1: no relaxation, which oscillates on "
          "Goodman and Bray's column).");
      }
      prm.leave_subsection();
    }

    /** Contact/Load continuation. */
    void
    declare_continuation_entries(ParameterHandler &prm)
    {
      prm.enter_subsection("Load continuation");
      {
        prm.declare_entry(
          "Load factors",
          "10, 5, 2, 1",
          Patterns::List(Patterns::Double(0.), 1),
          "The increment's load, from the last converged state, times each "
          "factor in turn, the fast iteration at each from the states of the "
          "last; the last factor must be 1 (the increment's load).");
      }
      prm.leave_subsection();
    }

  } // namespace



  void
  StateMethodParameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    declare_order_entries(prm);
    declare_newton_entries(prm);
    declare_lemke_entries(prm);
    declare_de_saxce_entries(prm);
    declare_continuation_entries(prm);
  }



  void
  StateMethodParameters::parse_parameters(dealii::ParameterHandler &prm)
  {
    methods               = parse_state_methods(prm.get("State method"));
    fast_stall_iterations = prm.get_integer("Fast iteration stall");
    last_concluded_first  = (prm.get("Method order") == "last concluded first");
    prm.enter_subsection("Semismooth Newton");
    {
      newton_max_iterations = prm.get_integer("Maximum iterations");
      newton_tolerance      = prm.get_double("Tolerance");
      proximal_stiffness    = prm.get_double("Proximal stiffness");
      proximal_steps        = prm.get_integer("Proximal steps");
    }
    prm.leave_subsection();
    prm.enter_subsection("Lemke");
    {
      lemke_max_variables       = prm.get_integer("Maximum variables");
      lemke_pivots_per_variable = prm.get_integer("Pivots per variable");
    }
    prm.leave_subsection();
    prm.enter_subsection("De Saxce");
    {
      de_saxce_max_qps    = prm.get_integer("Maximum QPs");
      de_saxce_relaxation = prm.get_double("Relaxation");
      de_saxce_max_pairs  = prm.get_integer("Maximum pairs");
    }
    prm.leave_subsection();
    prm.enter_subsection("Load continuation");
    {
      continuation_factors.clear();
      for (const std::string &factor :
           dealii::Utilities::split_string_list(prm.get("Load factors")))
        continuation_factors.push_back(
          dealii::Utilities::string_to_double(factor));
    }
    prm.leave_subsection();
    AssertThrow(continuation_factors.back() == 1.,
                dealii::ExcMessage(
                  "Contact/Load continuation/Load factors: the last factor "
                  "must be 1, the increment's load (it is " +
                  dealii::Utilities::to_string(continuation_factors.back()) +
                  ")."));
    AssertThrow(std::all_of(continuation_factors.begin(),
                            continuation_factors.end(),
                            [](const double f) { return f > 0.; }),
                dealii::ExcMessage("Contact/Load continuation/Load factors: "
                                   "every factor must be positive."));
  }
} // namespace mbfem
