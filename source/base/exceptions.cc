#include <mbfem/base/exceptions.h>

#include <iostream>
#include <sstream>

namespace mbfem
{
  int
  exit_code(const ExceptionBase &e)
  {
    if (dynamic_cast<const Exceptions::ExcNoEquilibrium *>(&e))
      return 2;
    if (dynamic_cast<const Exceptions::ExcNotConvergedButAdmissible *>(&e))
      return 3;
    if (dynamic_cast<const Exceptions::ExcNoEquilibriumAlongMechanism *>(&e))
      return 4;
    return 1;
  }



  std::string
  message_of(const ExceptionBase &e)
  {
    std::ostringstream message;
    e.print_info(message);
    const std::string text  = message.str();
    const auto        first = text.find_first_not_of(" \n");
    return first == std::string::npos ? std::string() : text.substr(first);
  }



  QuietCerr::QuietCerr()
    : original(std::cerr.rdbuf(held.rdbuf()))
  {}



  QuietCerr::~QuietCerr()
  {
    std::cerr.rdbuf(original);
  }
} // namespace mbfem
