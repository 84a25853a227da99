#ifndef mbfem_output_screen_detail_h
#define mbfem_output_screen_detail_h

#include <mbfem/output/output.h>

#include <deal.II/base/conditional_ostream.h>

#include <fstream>
#include <map>
#include <memory>
#include <ostream>
#include <string>

namespace mbfem
{
  using namespace dealii;

  /**
   * Where the per-block and per-interface detail of a run goes: on the
   * screen for a model of a few blocks, into files beside the results for
   * a large one ('Output/Screen'), so that the screen of a 200-block slope
   * or a 1000-block wall stays a summary (issue 60): the counts, the mesh,
   * the interfaces by joint set, a line per increment.
   */
  class ScreenDetail
  {
  public:
    /**
     * The mode of @p output for a model of @p n_blocks blocks; files are
     * written where @p pcout is active (rank 0).
     */
    ScreenDetail(const OutputParameters &output,
                 const unsigned int      n_blocks,
                 ConditionalOStream     &pcout);

    /** Whether the detail goes to files. */
    bool
    summary() const;

    /**
     * The stream for the detail of @p what ("blocks", "interfaces"): the
     * screen, or the file BASE-WHAT.txt in the output folder, opened (and
     * the folder made) at the first call.
     */
    ConditionalOStream &
    detail(const std::string &what);

    /** "detail per block in FILE, ..." for the screen; empty if none. */
    std::string
    files() const;

    /** Beyond this many blocks 'Screen = auto' writes the detail to files. */
    static constexpr unsigned int largest_full_screen = 20;

  private:
    const OutputParameters                                    &output;
    ConditionalOStream                                        &pcout;
    bool                                                       to_files = false;
    std::map<std::string, std::unique_ptr<std::ofstream>>      streams;
    std::map<std::string, std::unique_ptr<ConditionalOStream>> outs;
  };
} // namespace mbfem

#endif
