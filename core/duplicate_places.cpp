#include "duplicate_places.h"

#include <algorithm>

namespace tessera
{

DuplicatePlaces::Place& DuplicatePlaces::PlaceOfKept(std::int32_t kept)
{
  const auto known = this->KeyOf.find(kept);
  if (known != this->KeyOf.end())
  {
    return this->Places.at(known->second);
  }
  this->KeyOf.emplace(kept, kept);
  Place& place = this->Places[kept];
  place.Kept = kept;
  return place;
}

void DuplicatePlaces::AddCopy(std::int32_t copy, std::int32_t kept)
{
  Place& place = this->PlaceOfKept(kept);
  this->KeyOf[copy] = this->KeyOf.at(kept);
  place.Copies.insert(copy);
}

void DuplicatePlaces::GiveWay(std::int32_t kept, std::int32_t newKept)
{
  Place& place = this->PlaceOfKept(kept);
  this->KeyOf[newKept] = this->KeyOf.at(kept);
  place.Kept = newKept;
  place.Copies.insert(kept);
}

void DuplicatePlaces::RemoveCopy(std::int32_t copy)
{
  const auto known = this->KeyOf.find(copy);
  if (known == this->KeyOf.end())
  {
    return;
  }
  const std::int32_t key = known->second;
  this->KeyOf.erase(known);
  Place& place = this->Places.at(key);
  place.Copies.erase(copy);
  if (place.Copies.empty())
  {
    this->KeyOf.erase(place.Kept);
    this->Places.erase(key);
  }
}

std::int32_t DuplicatePlaces::PromoteHeir(std::int32_t kept, bool& heirHasCopies)
{
  heirHasCopies = false;
  const auto known = this->KeyOf.find(kept);
  if (known == this->KeyOf.end())
  {
    return -1;
  }
  const std::int32_t key = known->second;
  this->KeyOf.erase(known);
  Place& place = this->Places.at(key);
  const std::int32_t heir = *place.Copies.begin(); // a place lives while it has copies
  place.Copies.erase(place.Copies.begin());
  place.Kept = heir;
  heirHasCopies = !place.Copies.empty();
  if (!heirHasCopies)
  {
    this->KeyOf.erase(heir);
    this->Places.erase(key);
  }
  return heir;
}

std::int32_t DuplicatePlaces::KeptOf(std::int32_t id) const
{
  const auto known = this->KeyOf.find(id);
  if (known == this->KeyOf.end())
  {
    return -1;
  }
  const std::int32_t kept = this->Places.at(known->second).Kept;
  return kept != id ? kept : -1;
}

std::vector<std::pair<std::int32_t, std::int32_t>> DuplicatePlaces::Pairs() const
{
  std::vector<std::pair<std::int32_t, std::int32_t>> pairs;
  this->ForEachPair(
    [&pairs](std::int32_t copy, std::int32_t kept) { pairs.emplace_back(copy, kept); });
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

// An estimate: the nodes of the hash maps and sets as libstdc++ makes them (a node holds its
// value and one or three pointers and a colour), plus the bucket arrays.
std::size_t DuplicatePlaces::Bytes() const
{
  std::size_t copies = 0;
  for (const auto& place : this->Places)
  {
    copies += place.second.Copies.size();
  }
  constexpr std::size_t mapNode = sizeof(void*) + sizeof(std::size_t);
  constexpr std::size_t setNode = 4 * sizeof(void*);
  return copies * setNode +
    this->Places.size() * (mapNode + sizeof(std::pair<const std::int32_t, Place>)) +
    this->KeyOf.size() * (mapNode + sizeof(std::pair<const std::int32_t, std::int32_t>)) +
    (this->Places.bucket_count() + this->KeyOf.bucket_count()) * sizeof(void*);
}

} // namespace tessera
