#include <mbfem/output/screen_detail.h>

#include <deal.II/base/exceptions.h>

#include <filesystem>

namespace mbfem
{
  ScreenDetail::ScreenDetail(const OutputParameters &output,
                             const unsigned int      n_blocks,
                             ConditionalOStream     &pcout)
    : output(output)
    , pcout(pcout)
    , to_files(output.screen == "summary" ||
               (output.screen == "auto" && n_blocks > largest_full_screen))
  {}



  bool
  ScreenDetail::summary() const
  {
    return to_files;
  }



  ConditionalOStream &
  ScreenDetail::detail(const std::string &what)
  {
    if (!to_files)
      return pcout;
    auto &out = outs[what];
    if (out == nullptr)
      {
        const std::string name =
          output.directory + "/" + output.base_name + "-" + what + ".txt";
        auto &stream = streams[what];
        if (pcout.is_active())
          {
            std::filesystem::create_directories(output.directory);
            stream = std::make_unique<std::ofstream>(name);
            AssertThrow(*stream,
                        ExcMessage("Cannot write '" + name +
                                   "' (Output/Screen = summary puts the "
                                   "per-" +
                                   what + " detail there)."));
          }
        out = std::make_unique<ConditionalOStream>(
          pcout.is_active() ? static_cast<std::ostream &>(*stream) :
                              pcout.get_stream(),
          pcout.is_active());
      }
    // Silent where the screen is (other ranks, strength reduction's trials).
    out->set_condition(pcout.is_active() && streams[what] != nullptr);
    return *out;
  }



  std::string
  ScreenDetail::files() const
  {
    std::string text;
    for (const auto &[what, out] : outs)
      text += (text.empty() ? "" : ", ") + std::string("per ") +
              (what == "blocks" ? "block" : "interface") + " in " +
              output.directory + "/" + output.base_name + "-" + what + ".txt";
    return text.empty() ? text : "detail " + text;
  }
} // namespace mbfem
