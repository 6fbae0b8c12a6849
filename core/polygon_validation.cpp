#include "polygon_validation.h"

#include "errors.h"
#include "predicates_inline.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <tuple>

namespace tessera
{

void CheckRingOffsets(const std::vector<std::size_t>& ringOffsets, std::size_t vertexCount)
{
  if (ringOffsets.size() < 2)
  {
    throw InputError(
      "ring offsets need at least 2 entries (one ring), got " + std::to_string(ringOffsets.size()));
  }
  if (ringOffsets.front() != 0)
  {
    throw InputError("ring offset 0 is " + std::to_string(ringOffsets.front()) + ", expected 0");
  }
  for (std::size_t r = 1; r < ringOffsets.size(); ++r)
  {
    if (ringOffsets[r] < ringOffsets[r - 1])
    {
      throw InputError("ring offset " + std::to_string(r) + " (" + std::to_string(ringOffsets[r]) +
        ") is smaller than the one before it");
    }
  }
  if (ringOffsets.back() != vertexCount)
  {
    throw InputError("last ring offset is " + std::to_string(ringOffsets.back()) +
      ", expected the vertex count " + std::to_string(vertexCount));
  }
}

namespace
{

void CheckFinite(const std::vector<std::size_t>& ringOffsets, const std::vector<Point2>& vertices)
{
  for (std::size_t r = 0; r + 1 < ringOffsets.size(); ++r)
  {
    for (std::size_t v = ringOffsets[r]; v < ringOffsets[r + 1]; ++v)
    {
      const Point2& p = vertices[v];
      if (!std::isfinite(p.x) || !std::isfinite(p.y))
      {
        const bool nan = std::isnan(p.x) || std::isnan(p.y);
        throw RingError("ring " + std::to_string(r) + " vertex " +
            std::to_string(v - ringOffsets[r]) + " has " +
            (nan ? "a NaN coordinate" : "an infinite coordinate"),
          { r });
      }
    }
  }
}

// A vertex equal to its successor adds a zero-length segment and nothing else; keeping the last of
// each run makes clean segment k the caller's segment SourceIndex[k].
CleanRings DropRepeats(const std::vector<std::size_t>& ringOffsets,
  const std::vector<Point2>& vertices,
  const std::vector<std::size_t>* segmentOf)
{
  CleanRings clean;
  clean.RingOffsets.push_back(0);
  for (std::size_t r = 0; r + 1 < ringOffsets.size(); ++r)
  {
    const std::size_t begin = ringOffsets[r];
    const std::size_t end = ringOffsets[r + 1];
    for (std::size_t v = begin; v < end; ++v)
    {
      const std::size_t next = NextInRing(v, begin, end);
      if (vertices[v] != vertices[next])
      {
        clean.Vertices.push_back(vertices[v]);
        clean.SourceIndex.push_back(segmentOf ? (*segmentOf)[v] : v - begin);
      }
    }
    const std::size_t kept = clean.Vertices.size() - clean.RingOffsets.back();
    if (kept < 3)
    {
      // (a ring of one vertex keeps none: that vertex repeats itself)
      const std::size_t given = end - begin;
      throw RingError("ring " + std::to_string(r) + " has " +
          (given < 3 ? std::to_string(given) + (given == 1 ? " vertex" : " vertices") +
                " (a polygon needs 3 or more)"
                     : "fewer than 3 distinct vertices (" + std::to_string(kept) +
                " after dropping repeated consecutive vertices)"),
        { r });
    }
    clean.RingOffsets.push_back(clean.Vertices.size());
  }
  return clean;
}

int Sign(double v)
{
  return (v > 0) - (v < 0);
}

struct Segment
{
  std::size_t Ring;
  std::size_t Start; // index into CleanRings::Vertices
  std::size_t End;
  double XMin, XMax, YMin, YMax;
};

std::vector<Segment> CollectSegments(const CleanRings& clean)
{
  std::vector<Segment> segments;
  segments.reserve(clean.Vertices.size());
  for (std::size_t r = 0; r + 1 < clean.RingOffsets.size(); ++r)
  {
    const std::size_t begin = clean.RingOffsets[r];
    const std::size_t end = clean.RingOffsets[r + 1];
    for (std::size_t v = begin; v < end; ++v)
    {
      const std::size_t next = NextInRing(v, begin, end);
      const Point2& a = clean.Vertices[v];
      const Point2& b = clean.Vertices[next];
      segments.push_back({ r,
        v,
        next,
        std::min(a.x, b.x),
        std::max(a.x, b.x),
        std::min(a.y, b.y),
        std::max(a.y, b.y) });
    }
  }
  return segments;
}

// Neighbouring segments p->x and x->q of one ring share x; they meet elsewhere only when they
// overlap, that is when q lies on the ray from x through p.
bool NeighboursOverlap(const Point2& p, const Point2& x, const Point2& q)
{
  return orient2d_fast(p, x, q) == 0 && Sign(q.x - x.x) == Sign(p.x - x.x) &&
    Sign(q.y - x.y) == Sign(p.y - x.y);
}

// Segment k of a ring runs from its vertex k to vertex k+1 (the last one back to vertex 0).
std::string Describe(const CleanRings& clean, const Segment& s)
{
  return "segment " + std::to_string(clean.SourceIndex[s.Start]);
}

// Clean segment s as the caller numbers it.
RingError::Segment Named(const CleanRings& clean, const Segment& s)
{
  return { s.Ring, clean.SourceIndex[s.Start] };
}

std::size_t PreviousVertex(const CleanRings& clean, std::size_t ring, std::size_t v)
{
  return v == clean.RingOffsets[ring] ? clean.RingOffsets[ring + 1] - 1 : v - 1;
}

std::size_t NextVertex(const CleanRings& clean, std::size_t ring, std::size_t v)
{
  return v + 1 == clean.RingOffsets[ring + 1] ? clean.RingOffsets[ring] : v + 1;
}

// The two points that a ring's rays from p pass through, where p is a point of its segment s: the
// one before p along the ring and the one after it (the segment's ends, inside it).
std::pair<Point2, Point2> RaysAt(const CleanRings& clean, const Segment& s, const Point2& p)
{
  const Point2& a = clean.Vertices[s.Start];
  const Point2& b = clean.Vertices[s.End];
  if (p == a)
  {
    return { clean.Vertices[PreviousVertex(clean, s.Ring, s.Start)], b };
  }
  if (p == b)
  {
    return { a, clean.Vertices[NextVertex(clean, s.Ring, s.End)] };
  }
  return { a, b };
}

// Whether the ray from p through d lies strictly inside the angle swept anticlockwise from the ray
// through a1 to the ray through a2 (three distinct rays from p), exactly.
bool InsideAngle(const Point2& p, const Point2& a1, const Point2& a2, const Point2& d)
{
  const int turn = orient2d_fast(p, a1, a2);
  const int fromFirst = orient2d_fast(p, a1, d);
  const int toSecond = orient2d_fast(p, d, a2);
  if (turn > 0)
  {
    return fromFirst > 0 && toSecond > 0; // an angle below 180 degrees
  }
  if (turn < 0)
  {
    return fromFirst > 0 || toSecond > 0; // above 180: all but the angle from a2 to a1
  }
  return fromFirst > 0; // a1 and a2 opposite: the half-plane left of the ray through a1
}

// Rings may touch at points and share stretches of boundary, but not cross. Each ring's boundary,
// less the points it shares with another ring, then lies on one side of that ring: inside it or
// outside it. A contact point p of rings A and B shows the side of each ray of B from p that does
// not run along A (inside A when it lies in the angle that A's inside makes at p), and all of
// them, at all contacts of the two rings, must show the same side; so must A's rays against B.
//
//          b1                          b1
//          |                           |
//    a1 ---p--- a2   touch       a1 ---p--- a2   cross: b1 on one side of A, b2 on the other
//         / \                          |
//       b2   b1, b2 both above A       b2
//
// A shared stretch shows the sides at its ends, where the rings part:
//
//       B \                 / B       adjacent parts: B leaves A on A's outside at both ends
//   A ====p================q==== A   (p..q shared; a B that left on the inside at one end and
//                                     the outside at the other would cross A along the stretch)
class ContactCheck
{
public:
  // Every pair of rings that met has shown a side of each to the other, unless the two run along
  // each other all the way round (then neither has a ray off the other): into RingContacts.
  void Finish()
  {
    if (this->Parted)
    {
      this->ReportCrossingAlongShared(*this->Parted);
    }
    for (const auto& [r, s] : this->Meeting)
    {
      const auto rs = this->InsideOther.find({ r, s });
      const auto sr = this->InsideOther.find({ s, r });
      if (rs == this->InsideOther.end() || sr == this->InsideOther.end())
      {
        throw RingError("ring " + std::to_string(r) + " and ring " + std::to_string(s) +
            " run along each other all the way round: a ring given twice (give it once: by the "
            "even-odd rule the two copies cancel, taking its region away), or an island that "
            "fills a hole exactly (leave both out: they cancel)",
          { r, s });
      }
      this->Clean.RingContacts.push_back({ r, s, rs->second.Inside });
      this->Clean.RingContacts.push_back({ s, r, sr->second.Inside });
    }
    std::sort(this->Clean.RingContacts.begin(),
      this->Clean.RingContacts.end(),
      [](const CleanRings::RingContact& a, const CleanRings::RingContact& b)
      { return a.Ring < b.Ring || (a.Ring == b.Ring && a.Other < b.Other); });
  }

  explicit ContactCheck(CleanRings& clean)
    : Clean(clean)
  {
    for (std::size_t r = 0; r + 1 < clean.RingOffsets.size(); ++r)
    {
      this->Orientation.push_back(RingOrientation(
        &clean.Vertices[clean.RingOffsets[r]], clean.RingOffsets[r + 1] - clean.RingOffsets[r]));
    }
  }

  // Segments s and t of different rings: throws InputError where the rings cross; records where
  // they meet (CleanRings::ContactsInsideSegments) and on which side of each other.
  void Check(const Segment& s, const Segment& t)
  {
    const Point2& a = this->Clean.Vertices[s.Start];
    const Point2& b = this->Clean.Vertices[s.End];
    const Point2& c = this->Clean.Vertices[t.Start];
    const Point2& d = this->Clean.Vertices[t.End];
    const int o1 = orient2d_fast(a, b, c);
    const int o2 = orient2d_fast(a, b, d);
    const int o3 = orient2d_fast(c, d, a);
    const int o4 = orient2d_fast(c, d, b);
    if (o1 * o2 < 0 && o3 * o4 < 0)
    {
      this->ReportCrossing(s, t); // the interiors cross
    }
    // Otherwise they meet, if at all, at ends of one lying on the other: one point, or the ends
    // of a stretch they share.
    Point2 points[4];
    int count = 0;
    const auto add = [&](bool on, const Point2& p)
    {
      if (on && std::find(points, points + count, p) == points + count)
      {
        points[count++] = p;
      }
    };
    add(o1 == 0 && OnSegment(a, b, c), c);
    add(o2 == 0 && OnSegment(a, b, d), d);
    add(o3 == 0 && OnSegment(c, d, a), a);
    add(o4 == 0 && OnSegment(c, d, b), b);
    for (int k = 0; k < count; ++k)
    {
      this->CheckPoint(s, t, points[k]);
    }
  }

private:
  void CheckPoint(const Segment& s, const Segment& t, const Point2& p)
  {
    const auto [aBack, aAhead] = RaysAt(this->Clean, s, p);
    const auto [bBack, bAhead] = RaysAt(this->Clean, t, p);
    const auto along = [&p](const Point2& ray, const Point2& one, const Point2& other)
    { return NeighboursOverlap(one, p, ray) || NeighboursOverlap(other, p, ray); };
    this->MarkInside(s, p);
    this->MarkInside(t, p);
    this->Meeting.insert({ std::min(s.Ring, t.Ring), std::max(s.Ring, t.Ring) });
    // The sides that the rays of each ring off the other show at p (-1: along the other).
    int bSides[2], aSides[2];
    for (int k = 0; k < 2; ++k)
    {
      const Point2& bRay = k == 0 ? bBack : bAhead;
      const Point2& aRay = k == 0 ? aBack : aAhead;
      bSides[k] = along(bRay, aBack, aAhead) ? -1 : this->Inside(s.Ring, p, aBack, aAhead, bRay);
      aSides[k] = along(aRay, bBack, bAhead) ? -1 : this->Inside(t.Ring, p, bBack, bAhead, aRay);
    }
    if ((bSides[0] >= 0 && bSides[1] >= 0 && bSides[0] != bSides[1]) ||
      (aSides[0] >= 0 && aSides[1] >= 0 && aSides[0] != aSides[1]))
    {
      this->ReportCrossing(s, t); // one ring passes through the other at p
    }
    for (int k = 0; k < 2; ++k)
    {
      if (bSides[k] >= 0)
      {
        this->Record(t.Ring, s.Ring, bSides[k] == 1, s, t);
      }
      if (aSides[k] >= 0)
      {
        this->Record(s.Ring, t.Ring, aSides[k] == 1, s, t);
      }
    }
  }

  // Whether the ray from p through d lies inside ring r, whose rays at p pass through back and
  // ahead: in the angle swept anticlockwise from ahead to back when r runs anticlockwise (its
  // inside on its left), from back to ahead when it runs clockwise.
  bool Inside(std::size_t r,
    const Point2& p,
    const Point2& back,
    const Point2& ahead,
    const Point2& d) const
  {
    return this->Orientation[r] > 0 ? InsideAngle(p, ahead, back, d)
                                    : InsideAngle(p, back, ahead, d);
  }

  // A side of ring off other, seen where segments s and t meet. One that differs from the side
  // first seen is kept until the sweep ends (Parted): the rings then cross, but a crossing found
  // at a point by then names the place better than the two contacts do.
  void Record(std::size_t ring, std::size_t other, bool inside, const Segment& s, const Segment& t)
  {
    const auto found = this->InsideOther.emplace(std::make_pair(ring, other), Side{ inside, s, t });
    if (found.first->second.Inside != inside && !this->Parted)
    {
      this->Parted = PartedSides{ ring, other, found.first->second, Side{ inside, s, t } };
    }
  }

  // p listed when it is a point inside segment s (not one of its ends).
  void MarkInside(const Segment& s, const Point2& p)
  {
    if (this->Clean.Vertices[s.Start] != p && this->Clean.Vertices[s.End] != p)
    {
      this->Clean.ContactsInsideSegments.emplace_back(s.Start, p);
    }
  }

  // The side a ring's boundary off another lies on, and the segments where it was seen.
  struct Side
  {
    bool Inside;
    Segment S, T;
  };
  struct PartedSides
  {
    std::size_t Ring, Other;
    Side First, Then;
  };

  [[noreturn]] void ReportCrossing(const Segment& s, const Segment& t) const
  {
    const std::vector<RingError::Segment> named = this->NamedInOrder(s, t);
    throw RingError(named[0].Name() + " and " + named[1].Name() + " cross" + NotCrossingRule(),
      { named[0].Ring, named[1].Ring },
      named);
  }

  // Ring's boundary off the other lay inside it at one contact and outside at another, and the two
  // crossed nowhere at a point: they cross along a stretch of boundary they share, whose ends the
  // two contacts are (or lead to).
  [[noreturn]] void ReportCrossingAlongShared(const PartedSides& parted) const
  {
    const std::string ring = "ring " + std::to_string(parted.Ring);
    const std::string other = "ring " + std::to_string(parted.Other);
    const auto side = [](const Side& s) { return std::string(s.Inside ? "inside" : "outside"); };
    const std::vector<RingError::Segment> first =
      this->NamedInOrder(parted.First.S, parted.First.T);
    const std::vector<RingError::Segment> then = this->NamedInOrder(parted.Then.S, parted.Then.T);
    std::string message = "ring " + std::to_string(std::min(parted.Ring, parted.Other)) +
      " and ring " + std::to_string(std::max(parted.Ring, parted.Other)) +
      " cross along boundary they share";
    std::vector<RingError::Segment> named = first;
    if (SameSegments(first, then))
    {
      message += ", where " + MeetingText(first) + ": " + ring + " leaves " + other + " on its " +
        side(parted.First) + " at one end and on its " + side(parted.Then) + " at the other";
    }
    else
    {
      message += ": off " + other + ", " + ring + " lies " + side(parted.First) + " it where " +
        MeetingText(first) + ", and " + side(parted.Then) + " it where " + MeetingText(then);
      named.insert(named.end(), then.begin(), then.end());
    }
    throw RingError(message + NotCrossingRule(),
      { std::min(parted.Ring, parted.Other), std::max(parted.Ring, parted.Other) },
      named);
  }

  // Segments s and t of two rings as the caller numbers them, the lesser ring's first.
  std::vector<RingError::Segment> NamedInOrder(const Segment& s, const Segment& t) const
  {
    const bool sFirst = s.Ring < t.Ring;
    return { Named(this->Clean, sFirst ? s : t), Named(this->Clean, sFirst ? t : s) };
  }

  static bool SameSegments(const std::vector<RingError::Segment>& a,
    const std::vector<RingError::Segment>& b)
  {
    return std::equal(a.begin(),
      a.end(),
      b.begin(),
      b.end(),
      [](const RingError::Segment& x, const RingError::Segment& y)
      { return x.Ring == y.Ring && x.Index == y.Index; });
  }

  // "ring 0 segment 2 meets ring 1 segment 5"
  static std::string MeetingText(const std::vector<RingError::Segment>& pair)
  {
    return pair[0].Name() + " meets " + pair[1].Name();
  }

  static std::string NotCrossingRule()
  {
    return " (rings may touch and share stretches of boundary, but not cross; holes and islands "
           "are separate rings)";
  }

  CleanRings& Clean;
  std::vector<int> Orientation;
  // (ring, other ring): the side the ring's boundary off the other lies on, as first seen.
  std::map<std::pair<std::size_t, std::size_t>, Side> InsideOther;
  std::optional<PartedSides> Parted; // the first pair of rings seen on both sides
  std::set<std::pair<std::size_t, std::size_t>> Meeting; // (lesser ring, greater ring)
};

// Neighbours in one ring share their common vertex; any other contact within a ring is a defect.
bool MeetsWithinRing(const CleanRings& clean, const Segment& s, const Segment& t)
{
  const Point2& a = clean.Vertices[s.Start];
  const Point2& b = clean.Vertices[s.End];
  const Point2& c = clean.Vertices[t.Start];
  const Point2& d = clean.Vertices[t.End];
  if (s.End == t.Start)
  {
    return NeighboursOverlap(a, b, d);
  }
  if (t.End == s.Start)
  {
    return NeighboursOverlap(c, d, b);
  }
  return SegmentsIntersect(a, b, c, d);
}

/// Rings may touch other rings at points, not themselves: a file from ArcGIS may give a lake
/// touching the outline as one ring that touches itself (a trial's catchment did).
const char* const SelfContactHint =
  " (a ring may touch other rings at points, not itself; a ring that touches itself to enclose a "
  "lake, as some ArcGIS files have, is made an outer ring and a hole by GDAL's ogr2ogr -makevalid "
  "or QGIS's Fix Geometries)";

[[noreturn]] void ReportSelfContact(const CleanRings& clean, const Segment& s, const Segment& t)
{
  const Segment& first = s.Start < t.Start ? s : t;
  const Segment& second = s.Start < t.Start ? t : s;
  const std::string ring = "ring " + std::to_string(first.Ring);
  const std::vector<RingError::Segment> named{ Named(clean, first), Named(clean, second) };
  const std::size_t begin = clean.RingOffsets[first.Ring];
  if (AllOnOneLine(&clean.Vertices[begin], clean.RingOffsets[first.Ring + 1] - begin))
  {
    // (a ring without area: its segments fold back over each other)
    throw RingError(ring + " has no area: its points lie on one line (" + Describe(clean, first) +
        " and " + Describe(clean, second) + " overlap)",
      { first.Ring },
      named);
  }
  throw RingError(ring + " is self-intersecting: " + Describe(clean, first) + " and " +
      Describe(clean, second) + " touch or cross" + SelfContactHint,
    { first.Ring },
    named);
}

// Sweep over segments sorted by their left end: a segment is compared only with those whose
// x-extents overlap it, then by y-extent, then exactly.
void CheckIntersections(CleanRings& clean)
{
  clean.ContactsInsideSegments.clear();
  clean.RingContacts.clear();
  ContactCheck contacts(clean);
  std::vector<Segment> segments = CollectSegments(clean);
  std::sort(segments.begin(),
    segments.end(),
    [](const Segment& s, const Segment& t)
    { return s.XMin < t.XMin || (s.XMin == t.XMin && s.Start < t.Start); });
  for (std::size_t i = 0; i < segments.size(); ++i)
  {
    const Segment& s = segments[i];
    for (std::size_t j = i + 1; j < segments.size() && segments[j].XMin <= s.XMax; ++j)
    {
      const Segment& t = segments[j];
      if (t.YMax < s.YMin || s.YMax < t.YMin)
      {
        continue;
      }
      if (s.Ring != t.Ring)
      {
        contacts.Check(s, t);
      }
      else if (MeetsWithinRing(clean, s, t))
      {
        ReportSelfContact(clean, s, t);
      }
    }
  }
  contacts.Finish();
}

} // namespace

CleanRings WithContactsAsVertices(const CleanRings& rings)
{
  if (rings.ContactsInsideSegments.empty())
  {
    return rings;
  }
  // By segment, then along it from its first vertex (both coordinates move monotonically there).
  std::vector<std::pair<std::size_t, Point2>> contacts = rings.ContactsInsideSegments;
  const auto along = [&rings](const std::pair<std::size_t, Point2>& c)
  {
    const Point2& a = rings.Vertices[c.first];
    return std::make_tuple(c.first, std::abs(c.second.x - a.x), std::abs(c.second.y - a.y));
  };
  std::sort(contacts.begin(),
    contacts.end(),
    [&along](const auto& c, const auto& d) { return along(c) < along(d); });
  contacts.erase(std::unique(contacts.begin(), contacts.end()), contacts.end());
  CleanRings out;
  out.RingContacts = rings.RingContacts;
  out.RingOffsets.push_back(0);
  std::size_t next = 0;
  for (std::size_t r = 0; r + 1 < rings.RingOffsets.size(); ++r)
  {
    for (std::size_t v = rings.RingOffsets[r]; v < rings.RingOffsets[r + 1]; ++v)
    {
      out.Vertices.push_back(rings.Vertices[v]);
      out.SourceIndex.push_back(rings.SourceIndex[v]);
      for (; next < contacts.size() && contacts[next].first == v; ++next)
      {
        out.Vertices.push_back(contacts[next].second);
        out.SourceIndex.push_back(rings.SourceIndex[v]);
      }
    }
    out.RingOffsets.push_back(out.Vertices.size());
  }
  return out;
}

int RingWinding(const Point2* ring, std::size_t count, const Point2& p)
{
  int winding = 0;
  for (std::size_t i = 0; i < count; ++i)
  {
    winding += RayCrossing(ring[i], ring[i + 1 == count ? 0 : i + 1], p);
  }
  return winding;
}

int RingOrientation(const Point2* ring, std::size_t count)
{
  const std::size_t lowest = LowestVertex(ring, count);
  const Point2& before = ring[lowest == 0 ? count - 1 : lowest - 1];
  const Point2& after = ring[lowest + 1 == count ? 0 : lowest + 1];
  return orient2d_fast(before, ring[lowest], after);
}

bool AllOnOneLine(const Point2* points, std::size_t count)
{
  const Point2* const end = points + count;
  const Point2* other = std::find_if(points, end, [&](const Point2& p) { return p != points[0]; });
  return std::all_of(
    other, end, [&](const Point2& p) { return orient2d_fast(points[0], *other, p) == 0; });
}

bool SegmentsIntersect(const Point2& a, const Point2& b, const Point2& c, const Point2& d)
{
  const int o1 = orient2d_fast(a, b, c);
  const int o2 = orient2d_fast(a, b, d);
  const int o3 = orient2d_fast(c, d, a);
  const int o4 = orient2d_fast(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0)
  {
    return true;
  }
  return (o1 == 0 && OnSegment(a, b, c)) || (o2 == 0 && OnSegment(a, b, d)) ||
    (o3 == 0 && OnSegment(c, d, a)) || (o4 == 0 && OnSegment(c, d, b));
}

CleanRings ValidateRings(const std::vector<std::size_t>& ringOffsets,
  const std::vector<Point2>& vertices,
  const std::vector<std::size_t>* segmentOf)
{
  CheckRingOffsets(ringOffsets, vertices.size());
  if (segmentOf && segmentOf->size() != vertices.size())
  {
    throw InputError("ValidateRings: " + std::to_string(segmentOf->size()) +
      " segment numbers for " + std::to_string(vertices.size()) + " vertices");
  }
  CheckFinite(ringOffsets, vertices);
  CleanRings clean = DropRepeats(ringOffsets, vertices, segmentOf);
  CheckIntersections(clean);
  return clean;
}

} // namespace tessera
