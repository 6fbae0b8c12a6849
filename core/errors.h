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

} // namespace tessera
