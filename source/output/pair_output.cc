#include <mbfem/output/pair_output.h>

#include <deal.II/base/utilities.h>

#include <cstdio>
#include <iomanip>
#include <sstream>

namespace mbfem
{
  namespace
  {
    /** Appends @p values to @p out as ",%.10e" each. */
    void
    append(std::ostringstream &out, std::initializer_list<double> values)
    {
      char buffer[32];
      for (const double value : values)
        {
          std::snprintf(buffer, sizeof(buffer), ",%.10e", value);
          out << buffer;
        }
    }



    template <int dim>
    std::string
    pair_table(const ContactSolver<dim>        &contact,
               const unsigned int               increment,
               const double                     time,
               const std::vector<double>       &water,
               const std::vector<unsigned int> &numbers)
    {
      const char        *axes[] = {"x", "y", "z"};
      std::ostringstream csv;
      csv << "# increment " << increment << ", t = " << time << "\n";
      csv << "pair,interface";
      for (unsigned int d = 0; d < dim; ++d)
        csv << "," << axes[d];
      csv << ",normal_force,normal_traction";
      for (unsigned int d = 1; d < dim; ++d)
        csv << ",tangential_force_" << d << ",tangential_traction_" << d;
      csv << ",gap";
      for (unsigned int d = 1; d < dim; ++d)
        csv << ",slip_" << d;
      csv << ",state,broken,area,initial_gap"
          << (water.empty() ? "" : ",water_pressure") << "\n";

      const auto &pairs = contact.pairs();
      for (unsigned int i = 0; i < pairs.size(); ++i)
        {
          const auto          &pair = pairs[i];
          const Point<dim>     x    = pair.midpoint();
          const Tensor<1, dim> rho  = contact.local_force(i);
          const Tensor<1, dim> s    = contact.slip(i);
          csv << (numbers.empty() ? i : numbers[i]) << ","
              << pair.interface + 1;
          for (unsigned int d = 0; d < dim; ++d)
            append(csv, {x[d]});
          for (unsigned int d = 0; d < dim; ++d)
            append(csv, {rho[d], rho[d] / pair.area});
          append(csv, {contact.gap(i)});
          for (unsigned int d = 1; d < dim; ++d)
            append(csv, {s[d]});
          csv << "," << to_string(contact.state(i)) << ","
              << (contact.broken(i) ? 1 : 0);
          append(csv, {pair.area, contact.starting_gap(i)});
          if (!water.empty())
            append(csv, {water[i]});
          csv << "\n";
        }
      return csv.str();
    }



    /** A DataArray element of @p n_components components. */
    std::string
    data_array(const std::string &type,
               const std::string &name,
               const unsigned int n_components,
               const std::string &values)
    {
      return "<DataArray type=\"" + type + "\" Name=\"" + name +
             "\" NumberOfComponents=\"" + std::to_string(n_components) +
             "\" format=\"ascii\">" + values + "</DataArray>\n";
    }



    template <int dim>
    std::string
    pair_point_set(const ContactSolver<dim>  &contact,
                   const std::vector<double> &water)
    {
      const auto        &pairs = contact.pairs();
      std::ostringstream points, state, traction, gap, slip, normal, pressure;
      pressure.precision(10);
      for (const double p : water)
        pressure << p << " ";
      for (std::ostringstream *stream : {&points, &traction, &gap, &slip})
        stream->precision(10);
      for (unsigned int i = 0; i < pairs.size(); ++i)
        {
          const auto          &pair = pairs[i];
          const Point<dim>     x    = pair.midpoint();
          const Tensor<1, dim> r    = contact.force(i) / pair.area;
          const Tensor<1, dim> s    = contact.slip(i);
          Tensor<1, dim>       slip_global;
          for (unsigned int d = 1; d < dim; ++d)
            slip_global += s[d] * pair.frame[d];
          for (unsigned int d = 0; d < 3; ++d)
            {
              points << (d < dim ? x[d] : 0.) << " ";
              traction << (d < dim ? r[d] : 0.) << " ";
              slip << (d < dim ? slip_global[d] : 0.) << " ";
              normal << (d < dim ? pair.frame[0][d] : 0.) << " ";
            }
          state << static_cast<int>(contact.state(i)) << " ";
          gap << contact.gap(i) << " ";
        }

      const unsigned int n = pairs.size();
      std::ostringstream connectivity, offsets, types;
      for (unsigned int i = 0; i < n; ++i)
        {
          connectivity << i << " ";
          offsets << i + 1 << " ";
          types << "1 "; // VTK_VERTEX
        }
      std::ostringstream vtu;
      vtu << "<?xml version=\"1.0\"?>\n"
             "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n"
             "<UnstructuredGrid><Piece NumberOfPoints=\""
          << n << "\" NumberOfCells=\"" << n << "\">\n"
          << "<Points>" << data_array("Float64", "points", 3, points.str())
          << "</Points>\n<Cells>\n"
          << data_array("Int32", "connectivity", 1, connectivity.str())
          << data_array("Int32", "offsets", 1, offsets.str())
          << data_array("UInt8", "types", 1, types.str())
          << "</Cells>\n<PointData Scalars=\"state\">\n"
          << data_array("Int32", "state", 1, state.str())
          << data_array("Float64", "traction", 3, traction.str())
          << data_array("Float64", "gap", 1, gap.str())
          << data_array("Float64", "slip", 3, slip.str())
          << data_array("Float64", "normal", 3, normal.str())
          << (water.empty() ?
                "" :
                data_array("Float64", "water_pressure", 1, pressure.str()))
          << "</PointData>\n</Piece></UnstructuredGrid>\n</VTKFile>\n";
      return vtu.str();
    }
  } // namespace



  template <int dim>
  std::string
  write_pair_files(const ContactSolver<dim>        &contact,
                   const OutputParameters          &output,
                   const unsigned int               increment,
                   const double                     time,
                   const std::vector<double>       &water_pressure,
                   const std::vector<unsigned int> &pair_numbers)
  {
    const std::string stem =
      output.base_name + "-pairs-" + Utilities::int_to_string(increment, 4);
    write_file_atomically(
      output.directory + "/" + stem + ".csv",
      pair_table(contact, increment, time, water_pressure, pair_numbers));
    if (!output.write_vtu)
      return "";
    write_file_atomically(output.directory + "/" + stem + ".vtu",
                          pair_point_set(contact, water_pressure));
    return stem + ".vtu";
  }



  template std::string
  write_pair_files(const ContactSolver<2> &,
                   const OutputParameters &,
                   const unsigned int,
                   const double,
                   const std::vector<double> &,
                   const std::vector<unsigned int> &);
  template std::string
  write_pair_files(const ContactSolver<3> &,
                   const OutputParameters &,
                   const unsigned int,
                   const double,
                   const std::vector<double> &,
                   const std::vector<unsigned int> &);
} // namespace mbfem
