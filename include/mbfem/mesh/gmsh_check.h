#ifndef mbfem_mesh_gmsh_check_h
#define mbfem_mesh_gmsh_check_h

#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

/**
 * @file The structure of a gmsh file, checked before deal.II's GridIn reads
 * it. GridIn trusts the file: a file cut off inside a quoted name loops
 * forever, a count larger than the file reads on for as long as the count
 * says, /dev/zero fills the memory, a cell of zero area ends in an internal
 * assertion, and cells dropped from the file or left out of every physical
 * group still run as another model. Every refusal names the file and the
 * line.
 */

namespace mbfem
{
  /**
   * The joints of a hand-made mesh: elements of dimension dim-1 (lines in
   * 2D, quadrilaterals in 3D) in a physical group that lie between two
   * cells. deal.II's GridIn refuses them (it takes a physical group of a
   * face for a boundary id), so they are taken out of the text it reads and
   * kept here for 'Contact/Joint sets' entries with a 'group'.
   */
  struct GmshJointElements
  {
    /** The name of each group, by physical tag (its number if unnamed). */
    std::map<long, std::string> names;
    /** Each element: its physical tag and its corners. */
    std::vector<std::pair<long, std::vector<std::array<double, 3>>>> elements;
    /** The file without these elements (empty if it has none). */
    std::string text_for_grid_in;
  };

  /**
   * Reads @p path once, line by line with a bounded line length, and checks
   * it as a gmsh ASCII mesh of version 2.2 or 4.1 for a @p dim-dimensional
   * model: a regular file of at most 4 GiB; sections opened and closed in
   * order; counts that match the lines that follow; quoted physical names;
   * every node an element names present and every node used by an element;
   * every cell of dimension @p dim in a physical group if any is (only if
   * @p groups_give_blocks: a 'Block id function' numbers the blocks
   * instead); no cell of zero area (volume). Returns the mesh's joints.
   */
  GmshJointElements
  check_gmsh_file(const std::string &path,
                  const unsigned int dim,
                  const bool         groups_give_blocks);
} // namespace mbfem

#endif
