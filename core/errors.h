#pragma once
// Errors thrown by the core. A VTK filter catches them and turns them into vtkErrorMacro.

#include <stdexcept>
#include <string>

namespace tessera
{

/// Bad input: the message names the bad value and where it is ("point 17 has a NaN coordinate").
class InputError : public std::invalid_argument
{
public:
  explicit InputError(const std::string& message)
    : std::invalid_argument(message)
  {
  }
};

/// value as the shortest decimal text that reads back as the same double, with "." whatever the
/// locale, for messages and records: "39.2", not "39.200000000000003"; "1020.0000001", not
/// "1020.000000"; "nan", "inf".
std::string NumberText(double value);

} // namespace tessera
