#include <mbfem/analysis/load_history.h>
#include <mbfem/base/text_input.h>

#include <deal.II/base/utilities.h>

#include <cmath>
#include <sstream>

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
      prm.declare_entry(
        "Stages",
        "",
        Patterns::Anything(),
        "Stages of construction or loading, separated by ';', each 'NAME: "
        "END TIME, INCREMENTS', e.g. 'self weight: 1, 2; filling: 2, 5; "
        "uplift: 3, 2'. A stage runs from the end of the one before (t = 0 "
        "for the first) to its end time in equal increments. Loads, water "
        "pressure and prescribed displacements stay functions of t, so a "
        "stage's own load is written in t (e.g. min(max(t - 1, 0), 1) for "
        "one that grows during a stage from t = 1 to 2). States, slips and "
        "plastic strains carry over from stage to stage; increments are "
        "numbered on through all stages, and the summary CSV names each "
        "one's stage. Given, it replaces 'Number of increments' and 'End "
        "time', which must then stay at 1.");
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
      parse_stages(prm.get("Stages"));
    }
    prm.leave_subsection();
  }



  void
  LoadHistory::parse_stages(const std::string &text)
  {
    stages.clear();
    if (Utilities::trim(text).empty())
      return;
    AssertThrow(n_increments == 1 && end_time == 1.,
                ExcMessage("Load history: 'Stages' gives the increments and "
                           "the end time; leave 'Number of increments' and "
                           "'End time' at 1 (one would be ignored)."));
    const std::string where = "Load history/Stages";
    n_increments            = 0;
    double previous         = 0.;
    for (const auto &entry : split_list(text, ';', where))
      {
        const auto colon = entry.rfind(':');
        AssertThrow(colon != std::string::npos && colon > 0,
                    ExcMessage(where + ": cannot read '" + entry +
                               "'; write 'NAME: END TIME, INCREMENTS'."));
        Stage stage;
        stage.name              = Utilities::trim(entry.substr(0, colon));
        const std::string place = where + ", stage '" + stage.name + "'";
        const auto values = split_list(entry.substr(colon + 1), ',', place);
        AssertThrow(values.size() == 2,
                    ExcMessage(place + ": give its end time and its number "
                                       "of increments, e.g. '2, 5'."));
        stage.end_time          = parse_finite_number(values[0], place);
        const double increments = parse_finite_number(values[1], place);
        AssertThrow(increments >= 1. && increments <= 1e5 &&
                      increments == std::floor(increments),
                    ExcMessage(place +
                               ": the number of increments must be "
                               "a whole number from 1 to 100000, "
                               "got '" +
                               values[1] + "'."));
        stage.n_increments = static_cast<unsigned int>(increments);
        std::ostringstream order;
        order << place << " ends at t = " << stage.end_time
              << ", not after the stage before it (t = " << previous
              << "): stages follow each other in time.";
        AssertThrow(stage.end_time > previous, ExcMessage(order.str()));
        AssertThrow(stage.name.find_first_of(",\"") == std::string::npos,
                    ExcMessage(place + ": a stage's name goes into the "
                                       "summary CSV; write it without ',' "
                                       "and '\"'."));
        for (const auto &other : stages)
          AssertThrow(other.name != stage.name,
                      ExcMessage(where + ": two stages are named '" +
                                 stage.name + "'."));
        previous = stage.end_time;
        n_increments += stage.n_increments;
        stages.push_back(stage);
      }
    end_time = previous;
  }



  double
  LoadHistory::time(const unsigned int k) const
  {
    if (stages.empty())
      return end_time * k / n_increments;
    if (k == 0)
      return 0.;
    const unsigned int s     = stage(k);
    unsigned int       first = 0; // increments before stage s
    for (unsigned int i = 0; i < s; ++i)
      first += stages[i].n_increments;
    const double start = (s == 0 ? 0. : stages[s - 1].end_time);
    return start +
           (stages[s].end_time - start) * (k - first) / stages[s].n_increments;
  }



  unsigned int
  LoadHistory::stage(const unsigned int k) const
  {
    unsigned int last = 0; // the last increment of stage s
    for (unsigned int s = 0; s < stages.size(); ++s)
      {
        last += stages[s].n_increments;
        if (k <= last)
          return s;
      }
    return stages.empty() ? 0 : stages.size() - 1;
  }



  bool
  LoadHistory::starts_stage(const unsigned int k) const
  {
    return has_stages() && k >= 1 && (k == 1 || stage(k - 1) != stage(k));
  }
} // namespace mbfem
