#pragma once
// The effective constraints of a window (window.h) by an angular sweep, in O(n log n): what the
// pairwise test (every constraint against every other, O(n^2)) finds, for the windows it can
// certify, and nothing for the others, which the pairwise test then names as empty or unbounded.

#include "window.h"

#include <optional>
#include <vector>

namespace tessera
{

/// Per constraint (finite, not a == b == 0), whether it is effective: its boundary line holds an
/// edge of positive length of the window. Given only for a window with an interior that is
/// bounded, and then equal to the pairwise test's answer: of constraints that are the same
/// half-plane, the first given is the effective one. Nothing for an empty or unbounded window, or
/// fewer than 3 constraints.
std::optional<std::vector<bool>> EffectiveBySweep(const std::vector<HalfPlane>& constraints);

} // namespace tessera
