// OrderByDistinctKeys (order_by_key.h): each key's position written into a slot table indexed by
// key, then the table read in key order.
#include "order_by_key.h"

#include "large_pages.h"

#include <cassert>

namespace tessera
{

std::vector<std::int32_t> OrderByDistinctKeys(const std::int32_t* keys,
  std::size_t count,
  std::size_t keyLimit)
{
  std::vector<std::int32_t> slot; // written at random: on huge pages
  AssignOnLargePages(slot, keyLimit, std::int32_t(-1));
  for (std::size_t k = 0; k < count; ++k)
  {
    assert(keys[k] >= 0 && std::size_t(keys[k]) < keyLimit && slot[keys[k]] < 0);
    slot[keys[k]] = static_cast<std::int32_t>(k);
  }
  std::vector<std::int32_t> order;
  ReserveOnLargePages(order, count);
  for (const std::int32_t k : slot)
  {
    if (k >= 0)
    {
      order.push_back(k);
    }
  }
  return order;
}

} // namespace tessera
