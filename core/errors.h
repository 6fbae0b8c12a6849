#pragma once
// Errors thrown by the core. A VTK filter catches them and turns them into vtkErrorMacro.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace tessera
{

/// A long computation stopped at its caller's request (its progress callback returned false):
/// not an error; the caller drops what was made.
class Cancelled : public std::runtime_error
{
public:
  Cancelled()
    : std::runtime_error("stopped at the caller's request")
  {
  }
};

/// Calls progress (if any) with the fraction done, and throws Cancelled when it answers false: a
/// long computation's report at a stage, where its caller may stop it.
inline void ReportOrStop(const std::function<bool(double)>& progress, double fraction)
{
  if (progress && !progress(fraction))
  {
    throw Cancelled();
  }
}

/// Bad input: the message names the bad value and where it is ("point 17 has a NaN coordinate").
class InputError : public std::invalid_argument
{
public:
  explicit InputError(const std::string& message)
    : std::invalid_argument(message)
  {
  }
};

/// An InputError about rings of a polygon input that names them by their index ("ring 3"); Rings
/// holds those indices, so that a caller who knows where each ring came from (a cell of a data
/// set) can say so.
class RingError : public InputError
{
public:
  /// Segment k of a ring, numbered as the caller gave the ring: from its vertex k to vertex k + 1
  /// (the last one back to vertex 0).
  struct Segment
  {
    std::size_t Ring;
    std::size_t Index;
    /// "ring 2 segment 5", as messages name it.
    std::string Name() const
    {
      return "ring " + std::to_string(this->Ring) + " segment " + std::to_string(this->Index);
    }
  };

  RingError(const std::string& message,
    std::vector<std::size_t> rings,
    std::vector<Segment> segments = {})
    : InputError(message)
    , Rings(std::move(rings))
    , Segments(std::move(segments))
  {
  }
  std::vector<std::size_t> Rings;
  /// The segments the message names, in its order: a caller who has the rings' coordinates can
  /// say where they run.
  std::vector<Segment> Segments;
};

/// An InputError about a tile given to a clip that is not convex (clip.h): a caller that knows
/// where such tiles come from can say what to do instead.
class NotConvexError : public InputError
{
public:
  using InputError::InputError;
};

/// value as the shortest decimal text that reads back as the same double, with "." whatever the
/// locale, for messages and records: "39.2", not "39.200000000000003"; "1020.0000001", not
/// "1020.000000"; "nan", "inf".
std::string NumberText(double value);

/// The first 20 of count names, nameOf(0), nameOf(1), ..., then ", ... (N in all)" when there are
/// more: only the names shown are made. For messages that list ids (the core's warnings, the
/// filters' lists of skipped or unused items).
template<class NameOf>
std::string ListNames(std::size_t count, const NameOf& nameOf)
{
  std::string out;
  for (std::size_t k = 0; k < count && k < 20; ++k)
  {
    out += (k ? ", " : "") + std::string(nameOf(k));
  }
  if (count > 20)
  {
    out += ", ... (" + std::to_string(count) + " in all)";
  }
  return out;
}

/// "point 3 (of point 0), point 5 (of point 1)": the first 20 (ListNames) of (copy, original)
/// pairs of points at one place, as the warnings that name repeated points give them.
std::string DuplicatePairNames(const std::vector<std::pair<std::int32_t, std::int32_t>>& pairs);

/// Below this a width or sigma s is refused (CheckPositiveScale): the 2 s^2 of a Gaussian, or the
/// s^2 of an inverse multiquadric, underflows to zero, and the field or curve becomes 0/0 = NaN.
constexpr double SmallestScale = 1e-150;

/// Throws InputError "<what> <value> is not a positive number" unless value is positive and
/// finite, and "<what> <value> is below 1e-150 ..." when it is below SmallestScale.
void CheckPositiveScale(double value, const std::string& what);

} // namespace tessera
