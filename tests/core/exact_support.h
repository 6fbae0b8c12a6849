#pragma once
// Test-only exact rational geometry (GMP): points and the shoelace area, shared by the tests that
// compare rounded results with exact ones.

#include <gmpxx.h>

#include <cstddef>
#include <vector>

namespace tessera_test
{

struct QPoint
{
  mpq_class x, y;
};

/// Signed area (positive anticlockwise) of the polygon ring, exactly.
inline mpq_class ExactArea(const std::vector<QPoint>& ring)
{
  mpq_class twice = 0;
  for (std::size_t i = 0; i < ring.size(); ++i)
  {
    const QPoint& a = ring[i];
    const QPoint& b = ring[(i + 1) % ring.size()];
    twice += a.x * b.y - b.x * a.y;
  }
  return twice / 2;
}

} // namespace tessera_test
