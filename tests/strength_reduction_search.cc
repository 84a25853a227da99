// The search of StrengthReduction on load histories stood in by a rule
// (converged iff F <= F_true), so that it can be checked alone:
//   (a) a statics bound equal to F_true (one block sliding on one plane):
//       three trials, F = 1 and the bracket [F_LP (1 - tol/2),
//       F_LP (1 + tol/4)] around it;
//   (b) F_true 10 % below the bound (a heel that opens): the steps down
//       from the bound, then bisection;
//   (c) no bound (the certificate says above 1000), F_true = 3.7: the
//       steps up from F = 1;
//   (d) F = 1 fails (F_true = 0.4), bound 0.4.
// Each case prints its trials and must end with a bracket of relative
// width at most the tolerance that holds F_true.

#include <mbfem/analysis/strength_reduction.h>

#include <cmath>
#include <iostream>
#include <limits>

using namespace mbfem;

void
run_case(const std::string &name, const double f_true, const double bound)
{
  StrengthReductionParameters parameters;
  std::cout << "case " << name << ": F_true = " << f_true << "\n";
  StrengthReduction search(parameters, std::cout, true);
  const double      f     = search.search([&](const double factor) {
    StrengthTrial trial;
    trial.outcome = (factor <= f_true ? StrengthTrial::Outcome::converged :
                                                 StrengthTrial::Outcome::no_equilibrium);
    trial.increments   = trial.converged();
    trial.n_increments = 1;
    trial.statics_bound =
      (factor == 1. ? bound : std::numeric_limits<double>::quiet_NaN());
    return trial;
  });
  const bool        holds = search.lower() <= f_true && f_true < search.upper();
  const bool        narrow =
    search.upper() - search.lower() <= parameters.tolerance * search.lower();
  std::cout << search.result_line() << "\n"
            << "  F = " << f << ", trials " << search.trials().size()
            << ", bracket holds F_true: " << (holds ? "yes" : "no")
            << ", narrower than the tolerance: " << (narrow ? "yes" : "no")
            << "\n\n";
}

int
main()
{
  run_case("a", 1.5, 1.5);
  run_case("b", 1.35, 1.5);
  run_case("c", 3.7, std::numeric_limits<double>::quiet_NaN());
  run_case("d", 0.4, 0.4);
}
