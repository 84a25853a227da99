#ifndef mbfem_output_pair_output_h
#define mbfem_output_pair_output_h

#include <mbfem/contact/contact_solver.h>
#include <mbfem/output/output.h>

#include <string>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * The contact pairs of one increment as files: a CSV table (a row per
   * pair: position, forces and tractions in the pair's frame, gap, slip,
   * state) and, with VTU output on, a VTU point set for ParaView (global
   * components: traction, slip, normal; state and gap as scalars). Both are
   * written atomically. Returns the VTU file's name (for the PVD index), or
   * "" without VTU output. With @p water_pressure (per pair), a column
   * and a point field 'water_pressure'. With @p pair_numbers, the 'pair'
   * column gives each pair's number in the whole model (stages that add
   * blocks solve over a subset of the pairs), so that it names the same
   * pair in every increment.
   */
  template <int dim>
  std::string
  write_pair_files(const ContactSolver<dim>        &contact,
                   const OutputParameters          &output,
                   const unsigned int               increment,
                   const double                     time,
                   const std::vector<double>       &water_pressure = {},
                   const std::vector<unsigned int> &pair_numbers   = {});
} // namespace mbfem

#endif
