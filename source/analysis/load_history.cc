#include <mbfem/analysis/load_history.h>
#include <mbfem/base/text_input.h>

#include <deal.II/base/types.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
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
      prm.declare_entry(
        "Added blocks",
        "",
        Patterns::Anything(),
        "Blocks that stages add (a lift of a dam, a backfill), separated by "
        "';', each 'STAGE: MATERIAL IDS', e.g. 'lift 2: 3; lift 3: 4, 5'. "
        "A block added by a stage is not there before it: it carries no "
        "load and touches nothing. At the start of its stage it is cast "
        "stress-free onto the blocks as they have deformed: its pairs start "
        "closed, stuck and unloaded where those blocks are, and its "
        "self-weight and loads grow from 0 to full over the stage's "
        "increments. Condensed formulation and elastic blocks only.");
      prm.declare_entry(
        "Removed blocks",
        "",
        Patterns::Anything(),
        "Blocks that stages remove (an excavation bench, a temporary "
        "support), separated by ';', each 'STAGE: MATERIAL IDS', e.g. "
        "'bench 1: 6'. At the start of its stage the block and its pairs "
        "are gone; the forces its pairs exerted on the blocks that stay are "
        "released over the stage's increments (from full to 0), so that "
        "friction follows the unloading. Not in the first stage.");
      prm.declare_entry(
        "Interfaces switched on",
        "",
        Patterns::Anything(),
        "Interfaces that stages switch on (a contraction joint grouted), "
        "separated by ';', each 'STAGE: NUMBERS', where a number counts the "
        "entries of 'Contact/Interfaces' from 1, e.g. 'grouting: 2'. Before "
        "its stage the interface does not exist: the blocks on its two "
        "sides do not touch there. At the start of the stage its pairs "
        "close where the blocks are, stuck and unloaded, whatever gap "
        "there was (the grout fills it).");
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
      parse_stage_lists(prm.get("Added blocks"),
                        "Added blocks",
                        &Stage::added_blocks);
      parse_stage_lists(prm.get("Removed blocks"),
                        "Removed blocks",
                        &Stage::removed_blocks);
      parse_stage_lists(prm.get("Interfaces switched on"),
                        "Interfaces switched on",
                        &Stage::interfaces_on);
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



  void
  LoadHistory::parse_stage_lists(const std::string        &text,
                                 const std::string        &entry,
                                 std::vector<unsigned int> Stage::*ids)
  {
    const std::string where = "Load history/" + entry;
    if (Utilities::trim(text).empty())
      return;
    AssertThrow(has_stages(),
                ExcMessage(where + " names stages, but 'Load history/Stages' "
                                   "declares none."));
    std::vector<unsigned int> seen;
    for (const auto &item : split_list(text, ';', where))
      {
        const auto colon = item.rfind(':');
        AssertThrow(colon != std::string::npos && colon > 0,
                    ExcMessage(where + ": cannot read '" + item +
                               "'; write 'STAGE: N, N'."));
        const std::string name = Utilities::trim(item.substr(0, colon));
        const auto        stage =
          std::find_if(stages.begin(), stages.end(), [&](const Stage &s) {
            return s.name == name;
          });
        std::string names;
        for (const auto &s : stages)
          names += (names.empty() ? "'" : ", '") + s.name + "'";
        AssertThrow(stage != stages.end(),
                    ExcMessage(where + ": no stage is named '" + name +
                               "' (the stages are " + names + ")."));
        const auto ids_of_stage =
          parse_id_list(item.substr(colon + 1), where + ", '" + name + "'");
        AssertThrow(!ids_of_stage.empty(),
                    ExcMessage(where + ", '" + name +
                               "': give the numbers after the ':'."));
        AssertThrow(stage != stages.begin(),
                    ExcMessage(where + ", '" + name +
                               "': the first stage starts the model; what "
                               "is there from the start needs no entry."));
        for (const unsigned int id : ids_of_stage)
          {
            AssertThrow(std::find(seen.begin(), seen.end(), id) == seen.end(),
                        ExcMessage(where + ": " + std::to_string(id) +
                                   " is named twice; a block is added or "
                                   "removed, and an interface switched on, "
                                   "once."));
            seen.push_back(id);
            ((*stage).*ids).push_back(id);
          }
      }
  }



  unsigned int
  LoadHistory::stage_adding_block(const unsigned int id) const
  {
    for (unsigned int s = 0; s < stages.size(); ++s)
      for (const unsigned int added : stages[s].added_blocks)
        if (added == id)
          return s;
    return numbers::invalid_unsigned_int;
  }



  unsigned int
  LoadHistory::stage_removing_block(const unsigned int id) const
  {
    for (unsigned int s = 0; s < stages.size(); ++s)
      for (const unsigned int removed : stages[s].removed_blocks)
        if (removed == id)
          return s;
    return numbers::invalid_unsigned_int;
  }



  unsigned int
  LoadHistory::stage_switching_on(const unsigned int number) const
  {
    for (unsigned int s = 0; s < stages.size(); ++s)
      for (const unsigned int on : stages[s].interfaces_on)
        if (on == number)
          return s;
    return numbers::invalid_unsigned_int;
  }



  bool
  LoadHistory::changes_model() const
  {
    return std::any_of(stages.begin(), stages.end(), [](const Stage &s) {
      return !s.added_blocks.empty() || !s.removed_blocks.empty() ||
             !s.interfaces_on.empty();
    });
  }



  std::pair<double, double>
  LoadHistory::stage_times(const unsigned int s) const
  {
    AssertIndexRange(s, stages.size());
    return {s == 0 ? 0. : stages[s - 1].end_time, stages[s].end_time};
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
