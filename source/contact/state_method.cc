#include <mbfem/contact/state_method.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <algorithm>

namespace mbfem
{
  namespace
  {
    const std::vector<StateMethod> all_methods = {
      StateMethod::fast,
      StateMethod::load_path,
      StateMethod::semismooth_newton,
      StateMethod::load_continuation};
  } // namespace



  std::string
  to_string(const StateMethod method)
  {
    switch (method)
      {
        case StateMethod::fast:
          return "fast";
        case StateMethod::load_path:
          return "load path";
        case StateMethod::semismooth_newton:
          return "semismooth Newton";
        default:
          return "load continuation";
      }
  }



  std::string
  state_method_names()
  {
    std::string names;
    for (const StateMethod method : all_methods)
      names += (names.empty() ? "" : "|") + to_string(method);
    return names;
  }



  std::vector<StateMethod>
  parse_state_methods(const std::string &text)
  {
    std::vector<StateMethod> methods;
    for (const std::string &name : dealii::Utilities::split_string_list(text))
      {
        const auto method = std::find_if(all_methods.begin(),
                                         all_methods.end(),
                                         [&](const StateMethod m) {
                                           return to_string(m) == name;
                                         });
        AssertThrow(method != all_methods.end(),
                    dealii::ExcMessage("Contact/State method: '" + name +
                                       "' is not a method; the methods are " +
                                       state_method_names() + "."));
        AssertThrow(std::find(methods.begin(), methods.end(), *method) ==
                      methods.end(),
                    dealii::ExcMessage("Contact/State method: '" + name +
                                       "' is listed twice."));
        methods.push_back(*method);
      }
    AssertThrow(!methods.empty(),
                dealii::ExcMessage(
                  "Contact/State method: name at least one method."));
    return methods;
  }



  std::string
  to_string(const std::vector<StateMethod> &methods)
  {
    std::string text;
    for (const StateMethod method : methods)
      text += (text.empty() ? "" : ", ") + to_string(method);
    return text;
  }
} // namespace mbfem
