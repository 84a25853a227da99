#include <mbfem/base/exceptions.h>

#include <sstream>

namespace mbfem
{
  std::string
  message_of(const ExceptionBase &e)
  {
    std::ostringstream message;
    e.print_info(message);
    const std::string text  = message.str();
    const auto        first = text.find_first_not_of(" \n");
    return first == std::string::npos ? std::string() : text.substr(first);
  }
} // namespace mbfem
