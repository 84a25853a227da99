#ifndef mbfem_multibody_problem_h
#define mbfem_multibody_problem_h

#include <mbfem/block.h>
#include <mbfem/contact_solver.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <memory>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  template <int dim>
  struct Parameters;

  /**
   * The multi-body finite element method from mesh to results: the mesh is
   * split into blocks (one per material id), each block is factorised once,
   * contact pairs are found on the declared interfaces, the blocks' contact
   * flexibilities are computed by unit loads, and the load history is
   * followed increment by increment (external response of every block,
   * contact-state iteration, field recovery, output). A mesh with one held
   * block and no interface is the plain elastic problem.
   */
  template <int dim>
  class MultiBodyProblem
  {
  public:
    MultiBodyProblem(Parameters<dim> &parameters, ConditionalOStream &pcout);

    void
    run();

    /** The blocks with their final fields (after run()). */
    const std::vector<std::unique_ptr<Block<dim>>> &
    get_blocks() const;

    /** The contact solver, or nullptr without interfaces. */
    const ContactSolver<dim> *
    get_contact() const;

  private:
    void
    make_blocks();

    void
    setup_blocks();

    void
    print_increment(const unsigned int k,
                    const double       time,
                    const unsigned int iterations) const;

    void
    print_errors(const double time) const;

    /**
     * Per interface: largest tractions, the extent of the closed and the
     * stuck pairs (2D: along x), and errors against Contact/Exact traction.
     */
    void
    print_interface_summary() const;

    /** The pairs as CSV and as a VTU point set, for this increment. */
    std::string
    write_pairs(const unsigned int k, const double time) const;

    Parameters<dim>                         &parameters;
    ConditionalOStream                      &pcout;
    TimerOutput                              timer;
    std::vector<std::unique_ptr<Block<dim>>> blocks;
    std::unique_ptr<ContactSolver<dim>>      contact;
  };
} // namespace mbfem

#endif
