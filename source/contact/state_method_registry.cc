// The state methods by name, in the default order of 'Contact/State
// method': the one place a method is registered. A new method is its own
// file pair (a class derived from StateMethodInterface, see
// state_method.h) and one line in the list below.

#include <mbfem/contact/continuation_state_method.h>
#include <mbfem/contact/de_saxce_state_method.h>
#include <mbfem/contact/fast_state_method.h>
#include <mbfem/contact/lemke_state_method.h>
#include <mbfem/contact/load_path_state_method.h>
#include <mbfem/contact/newton_state_method.h>
#include <mbfem/contact/state_method.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>

namespace mbfem
{
  namespace
  {
    template <int dim, typename Method>
    StateMethodEntry<dim>
    entry()
    {
      return {Method::name(), Method::description(), Method::traits(), []() {
                return std::make_unique<Method>();
              }};
    }
  } // namespace



  template <int dim>
  const std::vector<StateMethodEntry<dim>> &
  registered_state_methods()
  {
    static const std::vector<StateMethodEntry<dim>> methods = {
      entry<dim, FastStateMethod<dim>>(),
      entry<dim, LoadPathStateMethod<dim>>(),
      entry<dim, NewtonStateMethod<dim>>(),
      entry<dim, LemkeStateMethod<dim>>(),
      entry<dim, DeSaxceStateMethod<dim>>(),
      entry<dim, ContinuationStateMethod<dim>>()};
    return methods;
  }



  template <int dim>
  const StateMethodEntry<dim> &
  registered_state_method(const std::string &name)
  {
    const auto &methods = registered_state_methods<dim>();
    const auto  method =
      std::find_if(methods.begin(), methods.end(), [&](const auto &entry) {
        return entry.name == name;
      });
    AssertThrow(method != methods.end(),
                dealii::ExcMessage("Contact/State method: '" + name +
                                   "' is not a method; the methods are " +
                                   state_method_names() + "."));
    return *method;
  }



  template const std::vector<StateMethodEntry<2>> &
  registered_state_methods<2>();
  template const std::vector<StateMethodEntry<3>> &
  registered_state_methods<3>();
  template const StateMethodEntry<2> &
  registered_state_method<2>(const std::string &);
  template const StateMethodEntry<3> &
  registered_state_method<3>(const std::string &);
} // namespace mbfem
