#pragma once
// Small helpers shared by the core test programs (not part of the library).

#include "dirichlet_tessellation.h"

#include <cstdint>
#include <vector>

namespace tessera_test
{

/// Ids of the accepted points of a tessellation, ascending.
inline std::vector<std::int32_t> AcceptedIds(const tessera::DirichletTessellation& t)
{
  std::vector<std::int32_t> ids;
  for (std::int32_t id = 0; id < std::int32_t(t.PointCount()); ++id)
  {
    if (t.Status(id) == tessera::PointStatus::Accepted)
    {
      ids.push_back(id);
    }
  }
  return ids;
}

} // namespace tessera_test
