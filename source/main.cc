// mbfem: the multi-body finite element method for frictional contact
// between elastic blocks (Su & Zhao 2016), on deal.II.
//
//   mbfem FILE.prm              run the file (.prm or .json)
//   mbfem --print-parameters    every parameter with documentation

#include <mbfem/analysis/multibody_problem.h>
#include <mbfem/analysis/order_study.h>
#include <mbfem/analysis/parameters.h>
#include <mbfem/base/exceptions.h>
#include <mbfem/base/interruption.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <new>
#include <streambuf>
#include <string>
#include <system_error>
#include <vector>

namespace
{
  /**
   * Whether a launcher started this process (Open MPI's mpirun sets
   * OMPI_COMM_WORLD_SIZE; Slurm's srun and other PMIx or PMI launchers set
   * PMIX_RANK or PMI_RANK and PMI_SIZE): else it is an Open MPI singleton.
   */
  bool
  launched()
  {
    for (const char *variable :
         {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
      if (std::getenv(variable) != nullptr)
        return true;
    return false;
  }



  /** The run's own directory for Open MPI's session files, if any. */
  std::string own_session_directory;

  void
  remove_own_session_directory()
  {
    std::error_code error; // nothing to say if it cannot be removed
    std::filesystem::remove_all(own_session_directory, error);
  }

  /**
   * Run without mpirun, every mbfem is an Open MPI singleton, and Open MPI
   * 4.1 puts all singletons of a user under one /tmp/ompi.HOST.UID/jf.0,
   * which one that ends removes when it is empty: another that starts
   * then fails ("could not create its session directory", doc/testing.md).
   * A directory of the run's own, under TMPDIR or /tmp, removed at exit;
   * not under mpirun, and not where the user chose one.
   */
  void
  use_own_session_directory()
  {
    if (launched() || std::getenv("OMPI_MCA_orte_tmpdir_base") != nullptr)
      return;
    const char       *tmp = std::getenv("TMPDIR");
    const std::string pattern =
      std::string(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp") +
      "/mbfem-ompi-XXXXXX";
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    if (mkdtemp(name.data()) == nullptr)
      return; // Open MPI's own choice then
    own_session_directory = name.data();
    setenv("OMPI_MCA_orte_tmpdir_base", own_session_directory.c_str(), 1);
    std::atexit(remove_own_session_directory);
  }


  /**
   * Run without a launcher (launched()), Open MPI makes mbfem a singleton
   * and pays for what only several processes need; a value the user set
   * stays:
   * - a helper daemon (orted) for the one process, some 0.4 s of every run
   *   (a one-block model: 1.1 -> 0.7 s): an isolated singleton needs none;
   * - the default messaging layer (the cm PML) probes the network
   *   libraries (libfabric, PSM2), 0.2 to 0.3 s more (an MPI_Init and
   *   MPI_Finalize alone: 0.24 s, with the ob1 PML 0.03 s; `mbfem
   *   --version` 0.54 s, with it 0.26 s; doc/testing.md): ob1, which a
   *   singleton's messages to itself need nothing more than.
   */
  void
  use_singleton_settings()
  {
    if (launched())
      return;
    setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
    setenv("OMPI_MCA_pml", "ob1", 0);
  }



  /** Where the screen output of the ranks other than 0 goes. */
  class NullBuffer : public std::streambuf
  {
  protected:
    int
    overflow(int c) override
    {
      return c == EOF ? 0 : c;
    }
  };



  void
  print_usage(std::ostream &out)
  {
    out << "Usage: mbfem FILE.prm|FILE.json\n"
           "       mbfem --print-parameters [2|3] [prm|json]\n"
           "       mbfem --help\n\n"
           "Runs the multi-body finite element model described by the "
           "parameter file.\n"
           "--print-parameters writes every parameter with its default and "
           "documentation\n"
           "(for Dimension = 2 unless 3 is given), as a .prm file or as JSON "
           "(values only);\n"
           "the manual is doc/parameters.prm.\n";
  }



  template <int dim>
  void
  run(const std::string &filename, dealii::ConditionalOStream &pcout)
  {
    mbfem::Parameters<dim> parameters;
    mbfem::read_parameters(filename, parameters);
    mbfem::stop_if_signalled(-1); // a signal while starting up
    if (parameters.run.mode == "order study")
      {
        // No increments to finish: a signal ends the study at once.
        mbfem::release_termination_signals();
        mbfem::OrderStudy<dim>(parameters, pcout).run();
      }
    else
      // The set-up and the load stepping check for a signal between their
      // steps.
      mbfem::MultiBodyProblem<dim>(parameters, pcout).run();
  }



  /** What a run stopped by a signal says; main() exits with 128 + it. */
  int
  report_signal(const int signal, const std::string &where)
  {
    std::cout << std::flush;
    std::cerr << "\nmbfem: stopped by "
              << (signal == SIGINT  ? "SIGINT" :
                  signal == SIGTERM ? "SIGTERM" :
                                      strsignal(signal))
              << " " << where << "." << std::endl;
    return 128 + signal;
  }


  /**
   * mbfem --print-parameters [2|3] [prm|json]: every parameter with its
   * default and documentation, for writing an input file.
   */
  void
  print_parameters(const int argc, char *argv[])
  {
    using namespace dealii;
    const std::string dim    = (argc > 2 ? argv[2] : "2");
    const std::string format = (argc > 3 ? argv[3] : "prm");
    AssertThrow((dim == "2" || dim == "3") &&
                  (format == "prm" || format == "json"),
                ExcMessage("Use: mbfem --print-parameters [2|3] "
                           "[prm|json]"));
    ParameterHandler prm;
    if (dim == "3")
      mbfem::Parameters<3>::declare_parameters(prm);
    else
      mbfem::Parameters<2>::declare_parameters(prm);
    prm.print_parameters(std::cout,
                         format == "json" ? ParameterHandler::ShortJSON :
                                            ParameterHandler::PRM);
  }
  /**
   * After MPI is up: --help, --print-parameters, or the run of the file
   * named; the exit code.
   */
  int
  run_command(const int argc, char *argv[], dealii::ConditionalOStream &pcout)
  {
    using namespace dealii;
    const std::string first = (argc > 1 ? argv[1] : "");
    if (argc < 2 || first == "--help" || first == "-h")
      {
        print_usage(argc < 2 ? std::cerr : std::cout);
        return argc < 2 ? 1 : 0;
      }
    if (first == "--print-parameters")
      {
        print_parameters(argc, argv);
        return 0;
      }
    AssertThrow(argc == 2,
                ExcMessage("mbfem takes one parameter file; see --help."));

    const unsigned int dim = mbfem::read_dimension(first);
    if (dim == 2)
      run<2>(first, pcout);
    else
      run<3>(first, pcout);
    if (mbfem::received_signal() != 0)
      return report_signal(mbfem::received_signal(),
                           "after the last increment (its summary may be "
                           "incomplete); the files on disk are complete (the "
                           "PVD index lists the increments written)");
    return 0;
  }



  /** The exit code and message of a run stopped by a signal. */
  int
  report_interruption(const mbfem::Interrupted &stop)
  {
    if (stop.last_complete_increment == -2)
      return report_signal(stop.signal,
                           "during a trial of strength reduction; the "
                           "trials so far are in the strength-reduction "
                           "CSV, no results were written");
    if (stop.last_complete_increment < 0)
      return report_signal(stop.signal,
                           "during the set-up, before the first increment; "
                           "no results were written");
    return report_signal(stop.signal,
                         "after increment " +
                           std::to_string(stop.last_complete_increment) +
                           ", the last complete one; the files on disk are "
                           "complete (the PVD index lists the increments "
                           "written)");
  }
} // namespace



int
main(int argc, char *argv[])
{
  using namespace dealii;
  // A log written to a file shows each increment as it finishes, and a run
  // that is killed keeps the lines printed so far.
  std::setvbuf(stdout, nullptr, _IOLBF, BUFSIZ);
  // Open MPI's start-up resets SIGINT and SIGTERM to their default
  // action: held back until it is done, a signal then ends the run at its
  // first check, with mbfem's message.
  mbfem::hold_termination_signals();
  use_singleton_settings();
  use_own_session_directory();
  // Never freed: std::cout is flushed after main returns.
  NullBuffer *const silent = new NullBuffer;
  try
    {
      Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      mbfem::catch_termination_signals();
      // Under mpirun every rank runs the same contact iteration and meets
      // the same errors; rank 0 speaks for them (doc/parallel.md).
      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
        {
          std::cout.rdbuf(silent);
          std::cerr.rdbuf(silent);
        }
      ConditionalOStream pcout(
        std::cout, Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0);

      return run_command(argc, argv, pcout);
    }
  catch (mbfem::Interrupted &stop)
    {
      return report_interruption(stop);
    }
  catch (ExceptionBase &exc)
    {
      // The user-facing part only: where in deal.II an error was raised is
      // of no use to someone fixing their input file.
      std::cerr << "\nmbfem: error\n";
      exc.print_info(std::cerr);
      std::cerr << "Aborting." << std::endl;
      return mbfem::exit_code(exc); // 2, 3, 4: see base/exceptions.h
    }
  catch (std::filesystem::filesystem_error &exc)
    {
      std::cerr << "\nmbfem: error\nA file operation on <"
                << exc.path1().string() << "> failed: " << exc.code().message()
                << ".\nAborting." << std::endl;
      return 1;
    }
  catch (std::bad_alloc &)
    {
      std::cerr << "\nmbfem: error\nThe model needs more memory than this "
                   "machine has (a mesh, a generator argument or a refinement "
                   "too large for it).\nAborting."
                << std::endl;
      return 1;
    }
  catch (std::exception &exc)
    {
      std::cerr << "\nmbfem: error\n"
                << exc.what() << "\nAborting." << std::endl;
      return 1;
    }
  catch (...)
    {
      std::cerr << "\nmbfem: error\nAn exception that mbfem does not know "
                   "ended the run: a defect of mbfem; please report it with "
                   "the parameter file.\nAborting."
                << std::endl;
      return 1;
    }
  return 0;
}
