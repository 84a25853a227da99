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
   * and a point field 'water_pressure'.
   */
  template <int dim>
  std::string
  write_pair_files(const ContactSolver<dim>  &contact,
                   const OutputParameters    &output,
                   const unsigned int         increment,
                   const double               time,
                   const std::vector<double> &water_pressure = {});
} // namespace mbfem

#endif
