#include <mbfem/base/parallel.h>
#include <mbfem/output/output.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/numerics/data_out.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace mbfem
{
  void
  OutputParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    {
      prm.declare_entry("Directory",
                        "results",
                        Patterns::Anything(),
                        "Folder for VTU/PVD and CSV results, created if "
                        "missing; relative to the working folder.");
      prm.declare_entry("Base name",
                        "solution",
                        Patterns::Anything(),
                        "Stem of the output file names: BASE.pvd indexes "
                        "BASE-blockB-STEP.vtu.");
      prm.declare_entry("Write VTU",
                        "true",
                        Patterns::Bool(),
                        "Write the displacement and stress fields of every "
                        "block at every load increment for ParaView.");
      prm.declare_entry(
        "Write contact problems",
        "false",
        Patterns::Bool(),
        "Write each increment's condensed contact problem u = W r + q + G "
        "alpha, G^T r + f = 0 with its joint data and the solution found, "
        "in FCLIB's conventions (per pair the normal component first): "
        "BASE-problem-STEP.json, -W.mtx and -G.mtx (Matrix Market); see "
        "doc/contact_problems.md. An increment on which the state iteration "
        "gives up (exit code 3) is always written, as "
        "BASE-failed-problem-STEP. Condensed formulation only.");
      prm.declare_entry(
        "Screen",
        "auto",
        Patterns::Selection("auto|full|summary"),
        "How much the screen shows. full: every block (cells, DoFs, "
        "material, free modes), every interface's resultant force at every "
        "increment and every interface's report at the end. summary: the "
        "counts, one line per increment and the run's summary; the detail "
        "per block goes to BASE-blocks.txt and per interface to "
        "BASE-interfaces.txt in the output folder, which the screen names. "
        "auto: full for at most 20 blocks, summary beyond.");
    }
    prm.leave_subsection();
  }



  void
  OutputParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    {
      directory              = prm.get("Directory");
      base_name              = prm.get("Base name");
      write_vtu              = prm.get_bool("Write VTU");
      write_contact_problems = prm.get_bool("Write contact problems");
      screen                 = prm.get("Screen");
    }
    prm.leave_subsection();
    AssertThrow(!base_name.empty() && base_name.find('/') == std::string::npos,
                ExcMessage("Output/Base name must be a plain file stem, got '" +
                           base_name + "'."));
    check_directory(directory);
  }



  void
  OutputParameters::check_directory(const std::string &directory)
  {
    // A path of thousands of characters is shown by its start and length.
    const std::string shown =
      (directory.size() <= 80 ?
         directory :
         directory.substr(0, 60) + "... (" + std::to_string(directory.size()) +
           " characters)");
    const std::string where = "Output/Directory = '" + shown + "'";
    AssertThrow(!Utilities::trim(directory).empty(),
                ExcMessage("Output/Directory is empty: name a folder for the "
                           "results, e.g. 'results'."));
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path  path = fs::weakly_canonical(fs::absolute(directory), ec);
    AssertThrow(!ec,
                ExcMessage(where + " is not a usable path: " + ec.message() +
                           "."));
    // mbfem runs as root on CI and fresh machines: its CSVs must not land
    // among the system's files.
    const auto        first = std::next(path.begin()); // below the root
    const std::string top   = (first == path.end() ? "" : first->string());
    AssertThrow(path != path.root_path(),
                ExcMessage(where + " is the root folder; write the results "
                                   "to a folder of their own, e.g. "
                                   "'results'."));
    // /run and /dev/shm hold users' media and scratch space: allowed.
    static const std::set<std::string> system_folders = {"bin",
                                                         "boot",
                                                         "dev",
                                                         "etc",
                                                         "lib",
                                                         "lib32",
                                                         "lib64",
                                                         "proc",
                                                         "sbin",
                                                         "sys",
                                                         "usr"};
    const bool scratch = path.string().rfind("/dev/shm/", 0) == 0;
    AssertThrow(system_folders.count(top) == 0 || scratch,
                ExcMessage(where + " lies in the system folder /" + top +
                           "; write the results to a folder of their own, "
                           "e.g. 'results'."));
  }



  template <int dim>
  StressPostprocessor<dim>::StressPostprocessor(
    const Material                           &material,
    const InSituStress                       *in_situ,
    const std::vector<SymmetricTensor<2, 3>> &plastic_stress,
    const Mapping<dim>                       *mapping,
    const unsigned int                        degree)
    : material(material)
    , in_situ(in_situ != nullptr && in_situ->enabled ? in_situ : nullptr)
    , plastic_stress(plastic_stress)
    , mapping(mapping)
  {
    if (plastic_stress.empty())
      return;
    Assert(mapping != nullptr, ExcInternalError());
    // Which 1D node each point of QGauss<dim> sits on in each direction,
    // found from the coordinates, so that no ordering is assumed.
    const QGauss<1>   gauss_1d(degree + 1);
    const QGauss<dim> gauss(degree + 1);
    for (const Point<1> &x : gauss_1d.get_points())
      nodes.push_back(x[0]);
    for (const Point<dim> &x : gauss.get_points())
      {
        std::array<unsigned int, dim> index;
        for (unsigned int d = 0; d < dim; ++d)
          {
            index[d] = 0;
            for (unsigned int k = 1; k < nodes.size(); ++k)
              if (std::abs(x[d] - nodes[k]) < std::abs(x[d] - nodes[index[d]]))
                index[d] = k;
          }
        node_of_point.push_back(index);
      }
  }



  template <int dim>
  SymmetricTensor<2, 3>
  StressPostprocessor<dim>::interpolated_plastic_stress(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const Point<dim>                                     &point) const
  {
    const unsigned int n_q   = node_of_point.size();
    const std::size_t  first = cell->active_cell_index() * n_q;
    Point<dim>         unit;
    try
      {
        unit = mapping->transform_real_to_unit_cell(cell, point);
      }
    catch (const typename Mapping<dim>::ExcTransformationFailed &)
      {
        // (Not seen so far; the cell's mean is the safe answer.)
        SymmetricTensor<2, 3> mean;
        for (unsigned int q = 0; q < n_q; ++q)
          mean += plastic_stress[first + q] / n_q;
        return mean;
      }
    // Lagrange polynomials through the Gauss nodes, a product over the
    // directions: exact at the Gauss points, degree p like the strain.
    std::array<std::vector<double>, dim> lagrange;
    for (unsigned int d = 0; d < dim; ++d)
      for (unsigned int k = 0; k < nodes.size(); ++k)
        {
          double value = 1.;
          for (unsigned int m = 0; m < nodes.size(); ++m)
            if (m != k)
              value *= (unit[d] - nodes[m]) / (nodes[k] - nodes[m]);
          lagrange[d].push_back(value);
        }
    SymmetricTensor<2, 3> result;
    for (unsigned int q = 0; q < n_q; ++q)
      {
        double weight = 1.;
        for (unsigned int d = 0; d < dim; ++d)
          weight *= lagrange[d][node_of_point[q][d]];
        result += weight * plastic_stress[first + q];
      }
    return result;
  }



  template <int dim>
  void
  StressPostprocessor<dim>::evaluate_vector_field(
    const DataPostprocessorInputs::Vector<dim> &inputs,
    std::vector<Vector<double>>                &computed_quantities) const
  {
    for (unsigned int p = 0; p < inputs.solution_gradients.size(); ++p)
      {
        Tensor<2, dim> grad;
        for (unsigned int d = 0; d < dim; ++d)
          grad[d] = inputs.solution_gradients[p][d];
        SymmetricTensor<2, 3> sigma = material.stress_3d<dim>(symmetrize(grad));
        if (in_situ)
          sigma += in_situ->stress_3d(inputs.evaluation_points[p]);
        if (!plastic_stress.empty())
          sigma -= interpolated_plastic_stress(inputs.template get_cell<dim>(),
                                               inputs.evaluation_points[p]);

        unsigned int k = 0;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            computed_quantities[p][k++] = sigma[i][j];
        if (dim == 2)
          computed_quantities[p][k++] = sigma[2][2];
        const std::array<double, 3> principal = principal_stresses(sigma);
        for (const double s : principal)
          computed_quantities[p][k++] = s;
        computed_quantities[p][k++] = von_mises_stress(sigma);
      }
  }



  template <int dim>
  std::vector<std::string>
  StressPostprocessor<dim>::get_names() const
  {
    std::vector<std::string> names(dim * dim, "stress");
    if (dim == 2)
      names.emplace_back("stress_zz");
    for (const std::string s : {"sigma_1", "sigma_2", "sigma_3", "von_Mises"})
      names.emplace_back(s);
    return names;
  }



  template <int dim>
  std::vector<DataComponentInterpretation::DataComponentInterpretation>
  StressPostprocessor<dim>::get_data_component_interpretation() const
  {
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
                       interpretation(dim * dim,
                     DataComponentInterpretation::component_is_part_of_tensor);
    const unsigned int n_scalars = (dim == 2 ? 5 : 4);
    for (unsigned int i = 0; i < n_scalars; ++i)
      interpretation.push_back(
        DataComponentInterpretation::component_is_scalar);
    return interpretation;
  }



  template <int dim>
  UpdateFlags
  StressPostprocessor<dim>::get_needed_update_flags() const
  {
    return in_situ || !plastic_stress.empty() ?
             update_gradients | update_quadrature_points :
             update_gradients;
  }



  OutputWriter::OutputWriter(const OutputParameters &parameters)
    : parameters(parameters)
  {
    create_output_directory(parameters.directory);
  }



  template <int dim>
  std::string
  OutputWriter::write_block(const Block<dim>  &block,
                            const unsigned int block_index,
                            const unsigned int step) const
  {
    const std::string name = parameters.base_name + "-block" +
                             Utilities::int_to_string(block_index, 2) + "-" +
                             Utilities::int_to_string(step, 4) + ".vtu";
    if (!block.is_local())
      return name; // another rank writes it

    DataOut<dim> data_out;
    data_out.attach_dof_handler(block.get_dof_handler());

    const std::vector<std::string> names(dim, "displacement");
    const std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(dim,
                     DataComponentInterpretation::component_is_part_of_vector);
    data_out.add_data_vector(block.get_solution(),
                             names,
                             DataOut<dim>::type_dof_data,
                             interpretation);
    std::vector<SymmetricTensor<2, 3>> plastic_stress;
    std::vector<double>                yielded, plastic_strain;
    block.plastic_state().cell_fields(
      block.get_triangulation().n_active_cells(),
      plastic_stress,
      yielded,
      plastic_strain);
    const StressPostprocessor<dim> stress(block.get_material(),
                                          block.get_in_situ_stress(),
                                          plastic_stress,
                                          &block.get_mapping(),
                                          block.get_fe().degree);
    data_out.add_data_vector(block.get_solution(), stress);
    Vector<float> yielded_cells(yielded.begin(), yielded.end());
    Vector<float> plastic_cells(plastic_strain.begin(), plastic_strain.end());
    if (block.is_plastic())
      {
        // Fraction of each cell's quadrature points on the yield surface,
        // and the largest equivalent plastic strain sqrt(2/3 eps_p:eps_p).
        data_out.add_data_vector(yielded_cells, "yielded");
        data_out.add_data_vector(plastic_cells, "plastic_strain");
      }

    Vector<float> block_id(block.get_triangulation().n_active_cells());
    block_id = static_cast<float>(block_index);
    data_out.add_data_vector(block_id, "block");

    const unsigned int degree = block.get_fe().degree;
    data_out.build_patches(block.get_mapping(),
                           degree,
                           DataOut<dim>::curved_inner_cells);

    DataOutBase::VtkFlags flags;
    flags.print_date_and_time      = false;
    flags.compression_level        = DataOutBase::VtkFlags::best_speed;
    flags.write_higher_order_cells = degree > 1;
    data_out.set_flags(flags);

    write_on_this_rank(parameters.directory + "/" + name,
                       [&](std::ostream &out) { data_out.write_vtu(out); });
    return name;
  }



  void
  OutputWriter::add_step(const double                    time,
                         const std::vector<std::string> &files)
  {
    steps.emplace_back(time, files);

    std::ostringstream pvd;
    pvd << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"Collection\" version=\"0.1\" "
           "byte_order=\"LittleEndian\">\n"
        << "  <Collection>\n";
    for (const auto &[t, names] : steps)
      for (unsigned int part = 0; part < names.size(); ++part)
        pvd << "    <DataSet timestep=\"" << t << "\" group=\"\" part=\""
            << part << "\" file=\"" << names[part] << "\"/>\n";
    pvd << "  </Collection>\n"
        << "</VTKFile>\n";
    write_file_atomically(pvd_file(), pvd.str());
  }



  std::string
  OutputWriter::pvd_file() const
  {
    return parameters.directory + "/" + parameters.base_name + ".pvd";
  }



  template class StressPostprocessor<2>;
  template class StressPostprocessor<3>;
  template std::string
  OutputWriter::write_block(const Block<2> &, unsigned int, unsigned int) const;
  template std::string
  OutputWriter::write_block(const Block<3> &, unsigned int, unsigned int) const;
} // namespace mbfem
