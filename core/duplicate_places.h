#pragma once
// The exact copies of a streamed tessellation, grouped by place: which accepted point each copy
// stands for, and which copy takes a removed point's place, each in O(log copies).
//
// A batch build lists its copies as sorted (copy, kept) pairs, 8 bytes each, searched by copy.
// Streaming also asks the reverse: when the kept point of a place is removed, the smallest of its
// copies takes its place and every other copy names that one. Scanning the pairs for them cost
// O(all copies) per removal (50 us at 10^5 places with a copy each, 14 us at 2 10^4), and erasing
// a pair from the sorted list moved the rest. Here a place keeps the set of its copies, and a
// copy names its place, not its kept point, so a new kept point changes one entry.
//
//   place key 7 (the first point kept there): kept 7, copies {12, 40}
//   Remove(7):  kept 12, copies {40}      (40 still names place 7)

#include <cstddef>
#include <cstdint>
#include <set>
#include <unordered_map>
#include <utility>
#include <vector>

namespace tessera
{

class DuplicatePlaces
{
public:
  /// Records copy as an exact copy of kept, an accepted point.
  void AddCopy(std::int32_t copy, std::int32_t kept);
  /// newKept, arriving at kept's place with a smaller input id, is kept there from now on, and
  /// kept becomes one of its copies.
  void GiveWay(std::int32_t kept, std::int32_t newKept);
  /// Forgets a copy (removed).
  void RemoveCopy(std::int32_t copy);
  /// kept is removed: the smallest of its copies is kept in its place and returned, with whether
  /// other copies remain; -1 when it had none.
  std::int32_t PromoteHeir(std::int32_t kept, bool& heirHasCopies);
  /// The point a copy stands for; -1 when id is no copy.
  std::int32_t KeptOf(std::int32_t id) const;
  /// (copy, kept) pairs, ascending by copy.
  std::vector<std::pair<std::int32_t, std::int32_t>> Pairs() const;
  /// Calls f(copy, kept) for every copy, in no order.
  template<typename F>
  void ForEachPair(F f) const
  {
    for (const auto& place : this->Places)
    {
      for (const std::int32_t copy : place.second.Copies)
      {
        f(copy, place.second.Kept);
      }
    }
  }
  std::size_t Bytes() const;

private:
  struct Place
  {
    std::int32_t Kept = -1;
    std::set<std::int32_t> Copies;
  };
  Place& PlaceOfKept(std::int32_t kept);

  std::unordered_map<std::int32_t, Place> Places;       ///< by place key
  std::unordered_map<std::int32_t, std::int32_t> KeyOf; ///< place key of each id kept or copied
};

} // namespace tessera
