#include "ring_insertions.h"

#include <algorithm>

namespace tessera
{

void SortAlongEdges(std::vector<RingInsertion>& insertions)
{
  std::sort(insertions.begin(),
    insertions.end(),
    [](const RingInsertion& a, const RingInsertion& b)
    { return a.Edge != b.Edge ? a.Edge < b.Edge : a.T < b.T; });
}

InsertedRings InsertIntoRings(const std::vector<std::size_t>& offsets,
  const std::vector<Point2>& vertices,
  const std::vector<RingInsertion>& insertions,
  SegmentNumbers segments)
{
  InsertedRings out;
  const bool numbered = segments == SegmentNumbers::Kept;
  out.Offsets.push_back(0);
  out.Vertices.reserve(vertices.size() + insertions.size());
  out.SegmentOf.reserve(numbered ? vertices.size() + insertions.size() : 0);
  auto inserted = insertions.begin(); // the first not yet placed
  for (std::size_t r = 0; r + 1 < offsets.size(); ++r)
  {
    const std::size_t begin = offsets[r], end = offsets[r + 1];
    for (std::size_t k = begin; k < end; ++k)
    {
      const std::size_t before = out.Vertices.size();
      out.Vertices.push_back(vertices[k]);
      for (; inserted != insertions.end() && inserted->Edge == k; ++inserted)
      {
        // (one point found on the edge from two rings, or equal to the edge's start: once)
        if (!(inserted->Vertex == out.Vertices.back()))
        {
          out.Vertices.push_back(inserted->Vertex);
          ++out.Inserted;
        }
      }
      if (numbered)
      {
        out.SegmentOf.insert(out.SegmentOf.end(), out.Vertices.size() - before, k - begin);
      }
    }
    out.Offsets.push_back(out.Vertices.size());
  }
  return out;
}

} // namespace tessera
