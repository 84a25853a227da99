#include <mbfem/analysis/load_history.h>

namespace mbfem
{
  void
  LoadHistory::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Load history");
    {
      prm.declare_entry("Number of increments",
                        "1",
                        Patterns::Integer(1),
                        "Number of equal load increments from t = 0 to "
                        "'End time'. Functions of t describe the loads.");
      prm.declare_entry("End time",
                        "1",
                        Patterns::Double(0.),
                        "Pseudo-time at the end of the load history.");
      prm.declare_entry(
        "Maximum step halvings",
        "0",
        Patterns::Integer(0, 20),
        "An increment that fails (contact states that cycle, a plastic "
        "iteration that does not converge) is retried from its start in "
        "steps of half the size, and of half that, up to this many times; "
        "the steps are committed like increments (friction and plasticity "
        "follow the finer path) but written only at the increments. 0: a "
        "failed increment ends the run.");
    }
    prm.leave_subsection();
  }



  void
  LoadHistory::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Load history");
    {
      n_increments = prm.get_integer("Number of increments");
      end_time     = prm.get_double("End time");
      max_halvings = prm.get_integer("Maximum step halvings");
      AssertThrow(end_time > 0.,
                  ExcMessage("Load history/End time = " + prm.get("End time") +
                             ": the increments run from t = 0 to the end "
                             "time, so it must be positive (at 0 every "
                             "increment would be at t = 0)."));
    }
    prm.leave_subsection();
  }



  double
  LoadHistory::time(const unsigned int k) const
  {
    return end_time * k / n_increments;
  }
} // namespace mbfem
