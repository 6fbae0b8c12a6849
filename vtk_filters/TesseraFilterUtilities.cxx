#include "TesseraFilterUtilities.h"

#include "vtkAbstractArray.h"
#include "vtkAlgorithm.h"
#include "vtkAlgorithmOutput.h"
#include "vtkCellArray.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkInformationVector.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPartitionedDataSet.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkStringArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVariant.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"

#include "errors.h"
#include "identical_rings.h"
#include "large_pages.h"
#include "polygon_area.h"
#include "segment_rings.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <map>
#include <optional>
#include <type_traits>
#include <set>
#include <sstream>

namespace tessera_vtk
{
namespace
{
template<typename Real>
void CopyXY(const Real* xyz, vtkIdType n, std::vector<tessera::Point2>& out)
{
  for (vtkIdType i = 0; i < n; ++i)
  {
    out[i] = { static_cast<double>(xyz[3 * i]), static_cast<double>(xyz[3 * i + 1]) };
  }
}
} // namespace

namespace
{
/// Whether a double holds the integer v exactly: its odd part fits in the 53 bits of a mantissa.
template<class Integer>
bool FitsADouble(Integer v)
{
  unsigned long long magnitude =
    v < 0 ? 0ULL - static_cast<unsigned long long>(v) : static_cast<unsigned long long>(v);
  while (magnitude != 0 && (magnitude & 1ULL) == 0)
  {
    magnitude >>= 1;
  }
  return magnitude < (1ULL << 53);
}

/// Throws naming the first point, of n points of 64-bit integers (3 components each, value(k)
/// the k-th), with an x or y that no double holds exactly.
template<class Value>
void CheckIntegerPoints(const Value& value, vtkIdType n)
{
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int axis = 0; axis < 2; ++axis)
    {
      const auto v = value(3 * i + axis);
      if (!FitsADouble(v))
      {
        throw tessera::InputError("point " + std::to_string(i) + " has the integer coordinate " +
          std::to_string(v) +
          ", which the doubles the tessellation computes in hold only rounded, to " +
          tessera::NumberText(static_cast<double>(v)) +
          " (beyond 2^53; 2^62 + 1 and 2^62 became one point): subtract an offset first");
      }
    }
  }
}

/// CheckIntegerPoints over an array of Integer: read in place where its values lie in one block
/// (AOS), else one by one as variants (an SOA array had passed unchecked).
template<class Integer>
void CheckIntegerArray(vtkDataArray* data)
{
  const vtkIdType n = data->GetNumberOfTuples();
  if (data->GetArrayType() == vtkAbstractArray::AoSDataArrayTemplate)
  {
    const Integer* values = static_cast<const Integer*>(data->GetVoidPointer(0));
    CheckIntegerPoints([values](vtkIdType k) { return values[k]; }, n);
  }
  else if (std::is_signed<Integer>::value)
  {
    CheckIntegerPoints([data](vtkIdType k) { return data->GetVariantValue(k).ToTypeInt64(); }, n);
  }
  else
  {
    CheckIntegerPoints([data](vtkIdType k) { return data->GetVariantValue(k).ToTypeUInt64(); }, n);
  }
}

/// Throws tessera::InputError naming the first point, of a 3-component array of 64-bit integers,
/// whose x or y no double holds exactly (some beyond 2^53: 2^62 + 1 and 2^62 became one point,
/// reported as a duplicate); nothing for arrays of other types.
void CheckIntegersFitDoubles(vtkDataArray* data)
{
  if (data->GetNumberOfComponents() != 3 || data->GetDataTypeSize() != 8)
  {
    return; // (points are 3 components; integers of 32 bits or fewer fit a double)
  }
  switch (data->GetDataType())
  {
    case VTK_LONG:
      CheckIntegerArray<long>(data);
      break;
    case VTK_LONG_LONG:
      CheckIntegerArray<long long>(data);
      break;
    case VTK_ID_TYPE:
      CheckIntegerArray<vtkIdType>(data);
      break;
    case VTK_UNSIGNED_LONG:
      CheckIntegerArray<unsigned long>(data);
      break;
    case VTK_UNSIGNED_LONG_LONG:
      CheckIntegerArray<unsigned long long>(data);
      break;
    default:
      break;
  }
}
} // namespace

std::vector<tessera::Point2> CopyPoints2D(vtkPoints* points)
{
  const vtkIdType n = points ? points->GetNumberOfPoints() : 0;
  std::vector<tessera::Point2> xy; // the engine's coordinates: read at random, on huge pages
  tessera::ResizeOnLargePages(xy, static_cast<std::size_t>(n));
  if (n == 0)
  {
    return xy;
  }
  vtkDataArray* data = points->GetData();
  // Direct reads for the two common layouts: a virtual call per point costs more than the
  // tessellation's own work per point at a million points.
  if (auto* d = vtkDoubleArray::SafeDownCast(data))
  {
    CopyXY(d->GetPointer(0), n, xy);
  }
  else if (auto* f = vtkFloatArray::SafeDownCast(data))
  {
    CopyXY(f->GetPointer(0), n, xy);
  }
  else
  {
    CheckIntegersFitDoubles(data);
    for (vtkIdType i = 0; i < n; ++i)
    {
      double p[3];
      points->GetPoint(i, p);
      xy[i] = { p[0], p[1] };
    }
  }
  return xy;
}

std::vector<tessera::Point2> ReadPoints2D(vtkPoints* points, vtkDataObject* joinedFrom)
{
  std::vector<tessera::Point2> xy = CopyPoints2D(points);
  for (std::size_t i = 0; i < xy.size(); ++i)
  {
    if (!std::isfinite(xy[i].x) || !std::isfinite(xy[i].y))
    {
      throw tessera::InputError(JoinedPointName(joinedFrom, static_cast<vtkIdType>(i)) +
        " has a NaN or infinite coordinate (" + tessera::NumberText(xy[i].x) + ", " +
        tessera::NumberText(xy[i].y) + ")");
    }
  }
  return xy;
}

std::string BoxText(const tessera::Box2& box)
{
  return "x " + tessera::NumberText(box.XMin) + " .. " + tessera::NumberText(box.XMax) + ", y " +
    tessera::NumberText(box.YMin) + " .. " + tessera::NumberText(box.YMax);
}

namespace
{
/// The x, y bounding box of points (at least one).
tessera::Box2 BoundsOfPoints(vtkPoints* points)
{
  double bounds[6];
  points->GetBounds(bounds);
  return { bounds[0], bounds[1], bounds[2], bounds[3] };
}

// value - pad, or the next double below value when rounding swallows pad (a pad far below the
// coordinates' ulp: points 0.25 apart at 1e15, a lone point at 1e16): the automatic window must
// keep every point strictly inside.
double Below(double value, double pad)
{
  const double padded = value - pad;
  return padded < value ? padded : std::nextafter(value, -HUGE_VAL);
}

double Above(double value, double pad)
{
  const double padded = value + pad;
  return padded > value ? padded : std::nextafter(value, HUGE_VAL);
}

/// advice: what to change ("set smaller WindowBounds ...").
[[noreturn]] void ThrowWindowTooLarge(const tessera::Box2& window, const std::string& advice)
{
  throw tessera::InputError(
    "the window (" + BoxText(window) + ") is too large: its area overflows a double; " + advice);
}

// The window, unless areas are needed and it is so large that they overflow (a Padding of 1e299
// gave NaN areas).
tessera::Window Representable(tessera::Window window, bool needArea, const std::string& advice)
{
  if (needArea && !std::isfinite(window.Area()))
  {
    ThrowWindowTooLarge(window.Bounds(), advice);
  }
  return window;
}

/// For tiles of points whose bounding box (box) has an area beyond the doubles: no padding
/// helps, and the message says so (it advised a smaller Padding where Padding was 0).
void CheckPointsSpan(const tessera::Box2& box)
{
  if (!std::isfinite((box.XMax - box.XMin) * (box.YMax - box.YMin)))
  {
    throw tessera::InputError("the points span " + BoxText(box) +
      ": the area of a window that holds them overflows a double, whatever the Padding, so their "
      "tiles' areas would too; scale the points down");
  }
}

const char* const SmallerBounds = "set smaller WindowBounds or window constraints";

/// What makes the automatic window as large as it is, and what to change, for points whose
/// bounding box has the larger side `side` (`smallest`: the window is already the smallest box of
/// doubles about them, an ulp beyond them each way, which no Padding changes). At Padding 0 the
/// window keeps a margin of 1e-9 of that side: points on a line 1e200 long were told to set a
/// smaller Padding than 0.
std::string PaddingAdvice(double padding, double side, bool smallest)
{
  if (smallest)
  {
    // (Padding plays no part, and the message blamed it: points at one place at 1e300, or an
    // ulp apart there)
    return "it is already the smallest window of doubles about the points, one unit in the last "
           "place beyond them each way, whatever the Padding: scale the points down";
  }
  if (padding == 0.0 && side > 0.0)
  {
    return "it is the points' bounding box with a margin of 1e-9 of its larger side (Padding 0): "
           "set WindowBounds close about the points, a Padding above 0 and below " +
      tessera::NumberText(DBL_MAX / (4.0 * side) / side) + ", or scale the points down";
  }
  return "it is the points' bounding box padded by " + tessera::NumberText(padding) +
    " of its larger side (Padding): set a smaller Padding, or WindowBounds";
}

/// "xmin, xmax, ymin, ymax" of WindowBounds, each as the user gave it.
std::string BoundsText(const double bounds[4])
{
  return tessera::NumberText(bounds[0]) + ", " + tessera::NumberText(bounds[1]) + ", " +
    tessera::NumberText(bounds[2]) + ", " + tessera::NumberText(bounds[3]);
}
} // namespace

const char* const ProjectionRecordName = "TesseraProjection";

void WriteProjectionRecord(vtkDataObject* data, const std::string& record)
{
  vtkNew<vtkStringArray> array;
  array->SetName(ProjectionRecordName);
  array->InsertNextValue(record);
  data->GetFieldData()->AddArray(array);
}

std::string ReadProjectionRecord(vtkDataObject* data)
{
  vtkFieldData* fd = data ? data->GetFieldData() : nullptr;
  auto* record =
    fd ? vtkStringArray::SafeDownCast(fd->GetAbstractArray(ProjectionRecordName)) : nullptr;
  return record && record->GetNumberOfValues() > 0 ? record->GetValue(0) : std::string();
}

std::string ProjectionRecordOf(vtkDataObject* data, const std::string& what)
{
  std::string record = ReadProjectionRecord(data);
  auto* composite = vtkCompositeDataSet::SafeDownCast(data);
  if (!record.empty() || !composite)
  {
    return record;
  }
  vtkSmartPointer<vtkCompositeDataIterator> it;
  it.TakeReference(composite->NewIterator());
  const BlockLabels labels(composite);
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    const std::string own = ReadProjectionRecord(it->GetCurrentDataObject());
    if (!own.empty() && !record.empty() && own != record)
    {
      throw tessera::InputError(what + " mixes blocks projected differently: " + labels.Of(it) +
        " with " + own + ", another with " + record);
    }
    record = own.empty() ? record : own;
  }
  return record;
}

tessera::Window CutToPoints(tessera::Window window, const std::vector<tessera::Point2>& points)
{
  if (points.empty())
  {
    return window;
  }
  const tessera::Box2 box = tessera::BoundsOf(points.data(), points.size());
  const double side = box.LargerSide();
  const double pad =
    side > 0.0 ? side : std::max({ 1.0, std::fabs(box.XMin), std::fabs(box.YMin) });
  const double xmin = Below(box.XMin, pad), xmax = Above(box.XMax, pad);
  const double ymin = Below(box.YMin, pad), ymax = Above(box.YMax, pad);
  if (!std::isfinite(xmin) || !std::isfinite(xmax) || !std::isfinite(ymin) || !std::isfinite(ymax))
  {
    return window;
  }
  std::vector<tessera::HalfPlane> constraints = window.EffectiveConstraints();
  constraints.push_back({ -1.0, 0.0, xmin });
  constraints.push_back({ 1.0, 0.0, -xmax });
  constraints.push_back({ 0.0, -1.0, ymin });
  constraints.push_back({ 0.0, 1.0, -ymax });
  // The window's own constraints keep their names; the box's sides are named for what they are.
  tessera::ConstraintNames names = window.EffectiveNames();
  for (const char* side : { "x > xmin", "x < xmax", "y > ymin", "y < ymax" })
  {
    names.Each.push_back(std::string("the side ") + side + " of the box around the points");
  }
  try
  {
    return tessera::Window(constraints, names);
  }
  catch (const tessera::InputError&)
  {
    return window;
  }
}

std::string EmptyBoundsWarning(const double bounds[4], bool withConstraints)
{
  const bool unset = bounds[0] == 0.0 && bounds[1] == 0.0 && bounds[2] == 0.0 && bounds[3] == 0.0;
  const bool nan = std::isnan(bounds[0]) || std::isnan(bounds[1]) || std::isnan(bounds[2]) ||
    std::isnan(bounds[3]); // an error names it (ChooseWindow): it is not an empty rectangle
  if (unset || nan || (bounds[0] < bounds[1] && bounds[2] < bounds[3]))
  {
    return std::string();
  }
  return "WindowBounds (xmin, xmax, ymin, ymax = " + BoundsText(bounds) +
    ") is an empty rectangle (" + (bounds[0] >= bounds[1] ? "xmin >= xmax" : "ymin >= ymax") +
    "), so it is ignored: the window is " +
    (withConstraints ? "the window constraints alone" : "the padded bounding box of the points") +
    ". Were the bounds given in another order, such as (xmin, ymin, xmax, ymax)?";
}

namespace
{

/// An InputError for a NaN or infinite WindowBounds value, naming it.
void CheckBoundsFinite(const double bounds[4])
{
  const char* names[4] = { "xmin", "xmax", "ymin", "ymax" };
  for (int k = 0; k < 4; ++k)
  {
    if (!std::isfinite(bounds[k]))
    {
      throw tessera::InputError(std::string("WindowBounds ") + names[k] + " is " +
        (std::isnan(bounds[k]) ? "NaN" : tessera::NumberText(bounds[k])) +
        " (xmin, xmax, ymin, ymax = " + BoundsText(bounds) + ")");
    }
  }
}

/// The window of the WindowBounds rectangle (when it is not empty) and the constraints (a, b, c
/// of a x + b y + c < 0, three numbers each); nothing when neither is given.
std::optional<tessera::Window> ConstraintsWindow(const double bounds[4],
  const std::vector<double>& constraints,
  bool needArea)
{
  std::vector<tessera::HalfPlane> halfPlanes;
  // Errors name the rectangle's sides as such and the user's constraints by their own numbers
  // (AddWindowConstraint's order, from 0), not by their place after the sides.
  tessera::ConstraintNames naming;
  const bool haveBounds = bounds[0] < bounds[1] && bounds[2] < bounds[3];
  if (haveBounds)
  {
    halfPlanes.push_back({ -1.0, 0.0, bounds[0] }); // x > xmin
    halfPlanes.push_back({ 1.0, 0.0, -bounds[1] }); // x < xmax
    halfPlanes.push_back({ 0.0, -1.0, bounds[2] }); // y > ymin
    halfPlanes.push_back({ 0.0, 1.0, -bounds[3] }); // y < ymax
    naming.Each = { "the WindowBounds side x > xmin",
      "the WindowBounds side x < xmax",
      "the WindowBounds side y > ymin",
      "the WindowBounds side y < ymax" };
  }
  std::size_t userCount = 0;
  for (std::size_t k = 0; k + 2 < constraints.size(); k += 3, ++userCount)
  {
    halfPlanes.push_back({ constraints[k], constraints[k + 1], constraints[k + 2] });
    naming.Each.push_back("window constraint " + std::to_string(userCount));
  }
  if (halfPlanes.empty())
  {
    return std::nullopt;
  }
  if (haveBounds && userCount == 0)
  {
    return Representable(
      tessera::Window::Rectangle(bounds[0], bounds[1], bounds[2], bounds[3], "the WindowBounds"),
      needArea,
      SmallerBounds);
  }
  if (haveBounds)
  {
    naming.All = "WindowBounds and the " + std::to_string(userCount) + " window constraint" +
      (userCount == 1 ? "" : "s");
  }
  try
  {
    return Representable(tessera::Window(halfPlanes, naming), needArea, SmallerBounds);
  }
  catch (const tessera::UnboundedWindowError& error)
  {
    // A constraint meant to cut a corner off the automatic window (ParaView's panel shows
    // WindowBounds empty by default) makes the constraints the whole window.
    if (haveBounds)
    {
      throw;
    }
    throw tessera::InputError(std::string(error.what()) +
      " (with WindowBounds empty the window is the constraints alone, not the points' padded "
      "bounding box: set WindowBounds for the constraints to cut, or add constraints that close "
      "the window)");
  }
}

/// The automatic window: the points' bounding box padded by padding times its larger side.
tessera::Window PaddedPointsWindow(double padding,
  const std::vector<tessera::Point2>& points,
  bool needArea)
{
  if (!(padding >= 0.0) || !std::isfinite(padding))
  {
    throw tessera::InputError(
      "Padding " + tessera::NumberText(padding) + " is not a finite number >= 0");
  }
  if (points.empty())
  {
    return tessera::Window::Rectangle(-1.0, 1.0, -1.0, 1.0);
  }
  const tessera::Box2 box = tessera::BoundsOf(points.data(), points.size());
  if (needArea)
  {
    CheckPointsSpan(box);
  }
  const double xmin = box.XMin, xmax = box.XMax, ymin = box.YMin, ymax = box.YMax;
  const double side = box.LargerSide();
  // Identical points: a unit square around them (a padding of a zero side would be empty).
  const double pad = side > 0.0 ? padding * side : 0.5;
  const double margin = side > 0.0 && pad == 0.0 ? side * 1e-9 : 0.0; // keep points strictly inside
  // A triangulation needs no area: its window need only hold the points, so a padding that would
  // carry it past the largest double (points of 1e308, or a Padding of 1e300) is cut to half the
  // room there is, which changes no face. Tiles need their areas: for them it stays an error.
  const double room =
    0.5 * std::min({ DBL_MAX - xmax, xmin + DBL_MAX, DBL_MAX - ymax, ymin + DBL_MAX });
  const double usable = needArea ? pad + margin : std::min(pad + margin, room);
  const double lower[2] = { Below(xmin, usable), Below(ymin, usable) };
  const double upper[2] = { Above(xmax, usable), Above(ymax, usable) };
  // Whether the window is the smallest of doubles about the points: no Padding makes it smaller.
  const bool smallest = lower[0] == std::nextafter(xmin, -HUGE_VAL) &&
    lower[1] == std::nextafter(ymin, -HUGE_VAL) && upper[0] == std::nextafter(xmax, HUGE_VAL) &&
    upper[1] == std::nextafter(ymax, HUGE_VAL);
  if (!std::isfinite(lower[0]) || !std::isfinite(lower[1]) || !std::isfinite(upper[0]) ||
    !std::isfinite(upper[1]))
  {
    if (!needArea)
    {
      // (the padding was cut to the room there is: only a point at the largest double is left)
      throw tessera::InputError("the points reach the largest double (" + BoxText(box) +
        "): no window of doubles holds them strictly inside; scale the points");
    }
    throw tessera::InputError("the automatic window reaches beyond the largest double: " +
      PaddingAdvice(padding, side, smallest)); // (before Rectangle refuses it)
  }
  return Representable(tessera::Window::Rectangle(lower[0],
                         upper[0],
                         lower[1],
                         upper[1],
                         "the automatic window's",
                         " (the points' bounding box, padded)"),
    needArea,
    PaddingAdvice(padding, side, smallest));
}

} // namespace

tessera::Window ChooseWindow(const double bounds[4],
  const std::vector<double>& constraints,
  double padding,
  const std::vector<tessera::Point2>& points,
  bool needArea)
{
  CheckBoundsFinite(bounds);
  if (std::optional<tessera::Window> window = ConstraintsWindow(bounds, constraints, needArea))
  {
    return std::move(*window);
  }
  return PaddedPointsWindow(padding, points, needArea);
}

tessera::Window ChooseWindowWithWarning(vtkAlgorithm* filter,
  const double bounds[4],
  const std::vector<double>& constraints,
  double padding,
  const std::vector<tessera::Point2>& points,
  bool needArea)
{
  tesseraWarnUnlessEmptyMacro(filter, EmptyBoundsWarning(bounds, !constraints.empty()));
  return ChooseWindow(bounds, constraints, padding, points, needArea);
}

void CheckChoice(const char* property, int value, const std::vector<const char*>& names)
{
  if (value >= 0 && static_cast<std::size_t>(value) < names.size())
  {
    return;
  }
  std::string choices;
  for (std::size_t k = 0; k < names.size(); ++k)
  {
    choices += (k ? ", " : "") + std::to_string(k) + " (" + names[k] + ")";
  }
  throw tessera::InputError(
    std::string(property) + " " + std::to_string(value) + " is not one of " + choices);
}

void AddIdFieldArray(vtkDataObject* data, const char* name, const std::vector<std::int32_t>& ids)
{
  vtkNew<vtkIdTypeArray> array;
  array->SetName(name);
  array->SetNumberOfValues(static_cast<vtkIdType>(ids.size()));
  for (std::size_t k = 0; k < ids.size(); ++k)
  {
    array->SetValue(static_cast<vtkIdType>(k), ids[k]);
  }
  data->GetFieldData()->AddArray(array);
}

namespace
{
void ListNonEmptyArraysFirst(vtkFieldData* field)
{
  const int count = field ? field->GetNumberOfArrays() : 0;
  if (count < 2 || field->GetAbstractArray(0)->GetNumberOfTuples() > 0)
  {
    return;
  }
  std::vector<vtkSmartPointer<vtkAbstractArray>> arrays;
  for (int k = 0; k < count; ++k)
  {
    arrays.emplace_back(field->GetAbstractArray(k));
  }
  std::stable_partition(arrays.begin(),
    arrays.end(),
    [](const vtkSmartPointer<vtkAbstractArray>& array) { return array->GetNumberOfTuples() > 0; });
  field->Initialize();
  for (const vtkSmartPointer<vtkAbstractArray>& array : arrays)
  {
    field->AddArray(array);
  }
}
} // namespace

bool DataBounds(vtkDataObject* data, double bounds[6])
{
  if (auto* set = vtkDataSet::SafeDownCast(data))
  {
    set->GetBounds(bounds);
  }
  else if (auto* composite = vtkCompositeDataSet::SafeDownCast(data))
  {
    composite->GetBounds(bounds);
  }
  else
  {
    return false;
  }
  return bounds[0] <= bounds[1] && bounds[2] <= bounds[3];
}

void MakeCompositeOrPolyDataOutput(vtkCompositeDataSet* composite,
  vtkInformationVector* outputVector)
{
  for (int port = 0; port < outputVector->GetNumberOfInformationObjects(); ++port)
  {
    vtkInformation* outInfo = outputVector->GetInformationObject(port);
    vtkDataObject* output = outInfo->Get(vtkDataObject::DATA_OBJECT());
    if (composite && (!output || !output->IsA(composite->GetClassName())))
    {
      vtkSmartPointer<vtkDataObject> made;
      made.TakeReference(composite->NewInstance());
      outInfo->Set(vtkDataObject::DATA_OBJECT(), made);
    }
    else if (!composite && !vtkPolyData::SafeDownCast(output))
    {
      outInfo->Set(vtkDataObject::DATA_OBJECT(), vtkSmartPointer<vtkPolyData>::New());
    }
  }
}

void AppendClosedLine(const tessera::Point2* ring,
  std::size_t count,
  int exponent,
  vtkPoints* points,
  vtkCellArray* lines)
{
  const vtkIdType first = points->GetNumberOfPoints();
  lines->InsertNextCell(static_cast<vtkIdType>(count + 1));
  for (std::size_t k = 0; k < count; ++k)
  {
    lines->InsertCellPoint(points->InsertNextPoint(
      std::ldexp(ring[k].x, -exponent), std::ldexp(ring[k].y, -exponent), 0.0));
  }
  lines->InsertCellPoint(first);
}

void ListNonEmptyFieldArraysFirst(vtkDataObject* data)
{
  if (!data)
  {
    return;
  }
  ListNonEmptyArraysFirst(data->GetFieldData());
  if (vtkCompositeDataSet* composite = vtkCompositeDataSet::SafeDownCast(data))
  {
    vtkSmartPointer<vtkCompositeDataIterator> block;
    block.TakeReference(composite->NewIterator());
    for (block->InitTraversal(); !block->IsDoneWithTraversal(); block->GoToNextItem())
    {
      ListNonEmptyArraysFirst(block->GetCurrentDataObject()->GetFieldData());
    }
  }
}

std::function<bool(double)> StageProgress(vtkAlgorithm* algorithm, double from, double to)
{
  return [algorithm, from, to](double fraction)
  {
    algorithm->UpdateProgress(from + fraction * (to - from));
    return !algorithm->GetAbortExecute();
  };
}

void ProgressOrStop(vtkAlgorithm* algorithm, double fraction)
{
  algorithm->UpdateProgress(fraction);
  if (algorithm->GetAbortExecute())
  {
    throw tessera::Cancelled();
  }
}

bool IsStop(const std::exception& e)
{
  return dynamic_cast<const tessera::Cancelled*>(&e) != nullptr;
}

bool IsClosedLine(vtkDataSet* data, vtkIdList* ids)
{
  const vtkIdType n = ids->GetNumberOfIds();
  if (n < 4)
  {
    return false;
  }
  double first[3], last[3];
  data->GetPoint(ids->GetId(0), first);
  data->GetPoint(ids->GetId(n - 1), last);
  return ids->GetId(0) == ids->GetId(n - 1) || (first[0] == last[0] && first[1] == last[1]);
}

namespace
{

/// Loose line segments (line cells, open polylines) of one vtkPolyData, by their ends, and their
/// cells: the core joins them into rings (JoinSegmentsAtEqualEnds).
class LooseSegments
{
public:
  void Add(vtkPolyData* poly, vtkIdList* ids, vtkIdType cell)
  {
    for (vtkIdType k = 0; k + 1 < ids->GetNumberOfIds(); ++k)
    {
      for (const vtkIdType id : { ids->GetId(k), ids->GetId(k + 1) })
      {
        double p[3];
        poly->GetPoint(id, p);
        this->Ends.push_back({ p[0], p[1] });
      }
      this->CellOf.push_back(cell);
    }
  }

  /// Appends the closed rings they form to rings (block: the prefix of their source); returns
  /// the cells with a segment in none.
  std::vector<vtkIdType> JoinInto(Rings& rings, const std::string& block) const
  {
    const tessera::PointRings joined = tessera::JoinSegmentsAtEqualEnds(this->Ends);
    for (std::size_t r = 0; r + 1 < joined.Offsets.size(); ++r)
    {
      rings.Vertices.insert(rings.Vertices.end(),
        joined.Vertices.begin() + std::ptrdiff_t(joined.Offsets[r]),
        joined.Vertices.begin() + std::ptrdiff_t(joined.Offsets[r + 1]));
      rings.Offsets.push_back(rings.Vertices.size());
      rings.Sources.push_back(
        (block.empty() ? std::string("a ring") : block + "a ring") + " of joined line cells");
    }
    std::vector<vtkIdType> unjoined;
    for (const std::size_t s : joined.Unjoined)
    {
      unjoined.push_back(this->CellOf[s]);
    }
    return unjoined;
  }

private:
  std::vector<tessera::Point2> Ends; ///< segment s: Ends[2s] to Ends[2s + 1]
  std::vector<vtkIdType> CellOf;
};

void AppendPolygonRings(vtkPolyData* poly, const std::string& block, Rings& rings)
{
  vtkNew<vtkIdList> ids;
  std::vector<vtkIdType> skipped;
  LooseSegments loose;
  for (vtkIdType c = 0; c < poly->GetNumberOfCells(); ++c)
  {
    const int type = poly->GetCellType(c);
    const bool isPolygon = type == VTK_POLYGON || type == VTK_TRIANGLE || type == VTK_QUAD;
    const bool isLine = type == VTK_LINE || type == VTK_POLY_LINE;
    if (!isPolygon && !isLine)
    {
      skipped.push_back(c);
      continue;
    }
    poly->GetCellPoints(c, ids);
    if (isLine && ids->GetNumberOfIds() < 2)
    {
      skipped.push_back(c); // (a line of 0 or 1 point: no segment to join; it was dropped unsaid)
      continue;
    }
    if (isLine && !IsClosedLine(poly, ids))
    {
      loose.Add(poly, ids, c); // joined with the others below
      continue;
    }
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      double p[3];
      poly->GetPoint(ids->GetId(k), p);
      rings.Vertices.push_back({ p[0], p[1] });
    }
    rings.Offsets.push_back(rings.Vertices.size());
    rings.Sources.push_back(block + "cell " + std::to_string(c));
  }
  const std::vector<vtkIdType> unjoined = loose.JoinInto(rings, block);
  skipped.insert(skipped.end(), unjoined.begin(), unjoined.end());
  std::sort(skipped.begin(), skipped.end());
  skipped.erase(std::unique(skipped.begin(), skipped.end()), skipped.end());
  if (!skipped.empty())
  {
    if (rings.SkippedCells == 0)
    {
      rings.FirstSkipped = block + "cell " + std::to_string(skipped.front());
    }
    rings.SkippedCells += skipped.size();
  }
}

/// Ghost flags are not attributes to carry: a cell's bits mean other things than a point's
/// (HIGHCONNECTIVITYCELL is HIDDENPOINT's bit), and a joined or tessellated set has no ghosts.
bool IsGhostArray(const char* name)
{
  return std::string(name) == vtkDataSetAttributes::GhostArrayName();
}

/// Per point of a point set whose cells are one vertex per point, that vertex's cell (its
/// attributes' row); empty when its cells are anything else.
std::vector<vtkIdType> VertexCellOfPoint(vtkPointSet* leaf)
{
  const vtkIdType n = leaf->GetNumberOfPoints();
  if (leaf->GetNumberOfCells() != n)
  {
    return {};
  }
  std::vector<vtkIdType> cellOf(static_cast<std::size_t>(n), -1);
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < n; ++c)
  {
    if (leaf->GetCellType(c) != VTK_VERTEX)
    {
      return {};
    }
    leaf->GetCellPoints(c, ids);
    const vtkIdType p = ids->GetNumberOfIds() == 1 ? ids->GetId(0) : -1;
    if (p < 0 || p >= n || cellOf[static_cast<std::size_t>(p)] >= 0)
    {
      return {};
    }
    cellOf[static_cast<std::size_t>(p)] = c;
  }
  return cellOf;
}

/// A leaf's array for its points, and the row of each point in it (null: the point's own id).
struct LeafArray
{
  vtkAbstractArray* Array = nullptr;
  const std::vector<vtkIdType>* RowOf = nullptr;

  vtkIdType Row(vtkIdType point) const
  {
    return this->RowOf ? (*this->RowOf)[static_cast<std::size_t>(point)] : point;
  }
};

/// The array `name` of a leaf: its point data's, else (cellOf not empty: vertex cells only) its
/// cell data's.
LeafArray FindLeafArray(vtkPointSet* leaf,
  const std::string& name,
  const std::vector<vtkIdType>& cellOf)
{
  if (vtkAbstractArray* own = leaf->GetPointData()->GetAbstractArray(name.c_str()))
  {
    return { own, nullptr };
  }
  if (!cellOf.empty())
  {
    return { leaf->GetCellData()->GetAbstractArray(name.c_str()), &cellOf };
  }
  return {};
}

/// The names of a leaf's point-data arrays, then of those cell-data arrays that no point-data
/// array shares a name with (carried when its cells are one vertex per point, else reported).
std::vector<std::string> ArrayNames(vtkPointSet* leaf)
{
  std::vector<std::string> names;
  for (vtkFieldData* data : { static_cast<vtkFieldData*>(leaf->GetPointData()),
         static_cast<vtkFieldData*>(leaf->GetCellData()) })
  {
    for (int k = 0; k < data->GetNumberOfArrays(); ++k)
    {
      const char* name = data->GetAbstractArray(k)->GetName();
      if (name && *name && !IsGhostArray(name) &&
        std::find(names.begin(), names.end(), name) == names.end())
      {
        names.emplace_back(name);
      }
    }
  }
  return names;
}

/// The named cell-data arrays of a point set (ghost flags aside) that have no point-data array
/// of their name (hidden false), or that a point-data array of their name hides (hidden true: the
/// point data's is the one carried; the cell data's was left out without a word).
std::vector<std::string> CellArrays(vtkPointSet* set, bool hidden)
{
  std::vector<std::string> names;
  vtkCellData* cells = set->GetCellData();
  for (int k = 0; k < cells->GetNumberOfArrays(); ++k)
  {
    const char* name = cells->GetAbstractArray(k)->GetName();
    if (name && *name && (set->GetPointData()->GetAbstractArray(name) != nullptr) == hidden &&
      !IsGhostArray(name))
    {
      names.emplace_back(name);
    }
  }
  return names;
}

std::vector<std::string> UncarriedCellArrays(vtkPointSet* set)
{
  return CellArrays(set, false);
}

/// 'a', 'b', ... (ListNames of the names, quoted).
std::string QuotedNames(const std::vector<std::string>& names)
{
  return ListNames(names.size(), [&](std::size_t k) { return "'" + names[k] + "'"; });
}

/// The cell-data arrays (among `names`; all when it is empty) that a point-data array of the same
/// name hides in a point set with cells.
std::vector<std::string> HiddenCellArrays(vtkPointSet* set, const std::vector<std::string>& names)
{
  std::vector<std::string> hidden;
  if (set->GetNumberOfCells() > 0)
  {
    for (const std::string& name : CellArrays(set, true))
    {
      if (names.empty() || std::find(names.begin(), names.end(), name) != names.end())
      {
        hidden.push_back(name);
      }
    }
  }
  return hidden;
}

/// "... cell-data array(s) 'a', 'b' ... not carried ..." for the arrays a point-data array of the
/// same name hides in a point set called `label`, or "".
std::string HiddenCellArraysProblem(vtkPointSet* set, const std::string& label)
{
  const std::vector<std::string> hidden = HiddenCellArrays(set, {});
  return hidden.empty() ? std::string()
                        : label + "'s cell-data array(s) " + QuotedNames(hidden) +
      " are not carried: its point data has arrays of the same names, which are carried instead";
}

/// A point set whose cells are one vertex per point (cellOf: VertexCellOfPoint) with its
/// vertices' cell-data arrays `names` added to its point data, each point given its vertex's
/// value: a shallow copy, so that the point data's roles (scalars, global ids, ...) and unnamed
/// arrays stay as they are.
vtkSmartPointer<vtkPointSet> WithVertexAttributes(vtkPointSet* points,
  const std::vector<vtkIdType>& cellOf,
  const std::vector<std::string>& names)
{
  vtkSmartPointer<vtkPointSet> copy;
  copy.TakeReference(points->NewInstance());
  copy->ShallowCopy(points);
  const vtkIdType n = points->GetNumberOfPoints();
  for (const std::string& name : names)
  {
    vtkAbstractArray* source = points->GetCellData()->GetAbstractArray(name.c_str());
    vtkSmartPointer<vtkAbstractArray> array;
    array.TakeReference(source->NewInstance());
    array->SetName(name.c_str());
    array->SetNumberOfComponents(source->GetNumberOfComponents());
    array->SetNumberOfTuples(n);
    for (vtkIdType p = 0; p < n; ++p)
    {
      array->SetTuple(p, cellOf[static_cast<std::size_t>(p)], source);
    }
    copy->GetPointData()->AddArray(array);
  }
  return copy;
}

/// A leaf of a composite data set of points, with the name the messages give it.
struct PointLeaf
{
  vtkPointSet* Set;
  std::string Label;
  std::vector<vtkIdType> CellOf; // VertexCellOfPoint
};

/// The leaves with points, in the composite's order. Throws tessera::InputError naming a leaf that
/// is not a point set, or one whose attribute arrays are short (CheckAttributeLengths).
std::vector<PointLeaf> PointLeaves(vtkCompositeDataSet* composite)
{
  const BlockLabels labels(composite);
  std::vector<PointLeaf> leaves;
  auto iter = vtk::TakeSmartPointer(composite->NewIterator());
  for (iter->InitTraversal(); !iter->IsDoneWithTraversal(); iter->GoToNextItem())
  {
    const std::string label = labels.Of(iter);
    auto* leaf = vtkPointSet::SafeDownCast(iter->GetCurrentDataObject());
    if (!leaf)
    {
      throw tessera::InputError(label + " of the points is a " +
        iter->GetCurrentDataObject()->GetClassName() + ", not a point set");
    }
    if (leaf->GetNumberOfPoints() > 0)
    {
      CheckAttributeLengths(leaf, label + " of the points");
      leaves.push_back({ leaf, label, VertexCellOfPoint(leaf) });
    }
  }
  return leaves;
}

} // namespace

std::string JoinedPointName(vtkDataObject* data, vtkIdType id)
{
  const std::string name = "point " + std::to_string(id);
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(data))
  {
    vtkIdType first = 0; // the leaf's first point in the joined numbering (as MergedPoints joins)
    for (const PointLeaf& leaf : PointLeaves(composite))
    {
      const vtkIdType count = leaf.Set->GetNumberOfPoints();
      if (id < first + count)
      {
        return name + " (point " + std::to_string(id - first) + " of " + leaf.Label + ")";
      }
      first += count;
    }
  }
  return name;
}

namespace
{

/// "block 1 ... of the points has 2 unnamed point-data array(s), not carried: ..." for a leaf
/// with unnamed point-data arrays (arrays are joined by name), or "".
std::string UnnamedArraysProblem(const PointLeaf& leaf)
{
  int unnamed = 0;
  vtkPointData* arrays = leaf.Set->GetPointData();
  for (int k = 0; k < arrays->GetNumberOfArrays(); ++k)
  {
    const char* name = arrays->GetAbstractArray(k)->GetName();
    unnamed += !name || !*name;
  }
  return unnamed == 0 ? std::string()
                      : leaf.Label + " of the points has " + std::to_string(unnamed) +
      " unnamed point-data array(s), not carried: the blocks' arrays are joined by name";
}

/// Why the leaves' arrays `name` cannot be joined (a leaf lacks it, or holds it in another type
/// or number of components than the first that has it), or "" when they can.
std::string JoinProblem(const std::vector<PointLeaf>& leaves, const std::string& name)
{
  const PointLeaf* model = nullptr;
  vtkAbstractArray* modelArray = nullptr;
  for (const PointLeaf& leaf : leaves)
  {
    vtkAbstractArray* array = FindLeafArray(leaf.Set, name, leaf.CellOf).Array;
    if (!array)
    {
      if (leaf.Set->GetCellData()->GetAbstractArray(name.c_str()))
      {
        return leaf.Label + " of the points holds '" + name +
          "' as cell data of cells that are not one vertex per point (polygons, lines, a "
          "multipoint feature), so "
          "its points cannot be given it";
      }
      std::string other;
      for (const PointLeaf& with : leaves)
      {
        if (FindLeafArray(with.Set, name, with.CellOf).Array)
        {
          other = ", which " + with.Label + " has";
          break;
        }
      }
      return leaf.Label + " of the points has no array '" + name + "'" + other;
    }
    if (!modelArray)
    {
      model = &leaf;
      modelArray = array;
    }
    else if (std::string(array->GetClassName()) != modelArray->GetClassName() ||
      array->GetNumberOfComponents() != modelArray->GetNumberOfComponents())
    {
      return leaf.Label + " of the points holds '" + name + "' as a " + array->GetClassName() +
        " of " + std::to_string(array->GetNumberOfComponents()) + " component(s) where " +
        model->Label + " holds a " + modelArray->GetClassName() + " of " +
        std::to_string(modelArray->GetNumberOfComponents());
    }
  }
  return std::string();
}

/// Asks, in a request's or an input's information, for the whole data set: piece 0 of 1, no
/// ghost levels (RequestWholeInputs, UpdatedData).
void AskForTheWhole(vtkInformation* info)
{
  info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
  info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
  info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
}

/// The path of each leaf below node (child indices joined by '/').
void CollectLeafPaths(vtkDataObject* node,
  const std::string& path,
  std::map<vtkDataObject*, std::string>& paths)
{
  const auto child = [&](unsigned int k, vtkDataObject* data)
  {
    if (data)
    {
      CollectLeafPaths(
        data, path.empty() ? std::to_string(k) : path + "/" + std::to_string(k), paths);
    }
  };
  if (auto* collection = vtkPartitionedDataSetCollection::SafeDownCast(node))
  {
    for (unsigned int k = 0; k < collection->GetNumberOfPartitionedDataSets(); ++k)
    {
      child(k, collection->GetPartitionedDataSet(k));
    }
  }
  else if (auto* partitioned = vtkPartitionedDataSet::SafeDownCast(node))
  {
    for (unsigned int k = 0; k < partitioned->GetNumberOfPartitions(); ++k)
    {
      child(k, partitioned->GetPartitionAsDataObject(k));
    }
  }
  else if (auto* blocks = vtkMultiBlockDataSet::SafeDownCast(node))
  {
    for (unsigned int k = 0; k < blocks->GetNumberOfBlocks(); ++k)
    {
      child(k, blocks->GetBlock(k));
    }
  }
  else if (!path.empty())
  {
    paths.emplace(node, path);
  }
}
} // namespace

vtkDataObject* UpdatedData(vtkAlgorithmOutput* connection)
{
  vtkAlgorithm* source = connection->GetProducer();
  const int port = connection->GetIndex();
  // The whole data, as RequestWholeInputs asks for it: a plain Update keeps the piece last asked
  // of the source (in ParaView under MPI, its own representation's), and the information made
  // from one piece (the ridge grouping's image extent, the areal average's time steps) then
  // differed from RequestData's, made from the whole.
  vtkNew<vtkInformationVector> requests;
  requests->SetNumberOfInformationObjects(port + 1);
  AskForTheWhole(requests->GetInformationObject(port));
  source->Update(port, requests);
  return source->GetOutputDataObject(port);
}

BlockLabels::BlockLabels(vtkCompositeDataSet* data)
{
  CollectLeafPaths(data, std::string(), this->Paths);
}

std::string BlockLabels::Of(vtkCompositeDataIterator* it) const
{
  const auto found = this->Paths.find(it->GetCurrentDataObject());
  std::string label = found != this->Paths.end()
    ? "block " + found->second + " (composite index " + std::to_string(it->GetCurrentFlatIndex())
    : "the block of composite index " + std::to_string(it->GetCurrentFlatIndex());
  if (it->HasCurrentMetaData() && it->GetCurrentMetaData()->Has(vtkCompositeDataSet::NAME()))
  {
    label += std::string(found != this->Paths.end() ? ", '" : " ('") +
      it->GetCurrentMetaData()->Get(vtkCompositeDataSet::NAME()) + "'";
    return label + ")";
  }
  return found != this->Paths.end() ? label + ")" : label;
}

std::string ArrayLabel(vtkAbstractArray* array)
{
  const char* name = array->GetName();
  return name && *name ? "'" + std::string(name) + "'" : std::string("without a name");
}

namespace
{
/// Calls visit(array, points, needed) for each point-data array of data (points true, needed its
/// number of points) and each cell-data array (points false, needed its number of cells).
template<class Visit>
void VisitAttributeArrays(vtkDataSet* data, Visit visit)
{
  for (const bool points : { true, false })
  {
    vtkFieldData* arrays = points ? static_cast<vtkFieldData*>(data->GetPointData())
                                  : static_cast<vtkFieldData*>(data->GetCellData());
    const vtkIdType needed = points ? data->GetNumberOfPoints() : data->GetNumberOfCells();
    for (int k = 0; k < arrays->GetNumberOfArrays(); ++k)
    {
      if (vtkAbstractArray* array = arrays->GetAbstractArray(k))
      {
        visit(array, points, needed);
      }
    }
  }
}
} // namespace

void CheckAttributeLengths(vtkDataSet* data, const std::string& what)
{
  VisitAttributeArrays(data,
    [&what](vtkAbstractArray* array, bool points, vtkIdType needed)
    {
      if (array->GetNumberOfTuples() < needed)
      {
        throw tessera::InputError(what + ": its " + (points ? "point" : "cell") + "-data array " +
          ArrayLabel(array) + " has " + std::to_string(array->GetNumberOfTuples()) +
          " value(s) for " + std::to_string(needed) + (points ? " points" : " cells"));
      }
    });
}

std::vector<std::string> LongAttributeWarnings(vtkDataSet* data,
  const std::string& what,
  bool pointData,
  const std::vector<std::string>& names)
{
  std::vector<std::string> warnings;
  VisitAttributeArrays(data,
    [&](vtkAbstractArray* array, bool points, vtkIdType needed)
    {
      const vtkIdType count = array->GetNumberOfTuples();
      if (points != pointData || count <= needed)
      {
        return;
      }
      const char* name = array->GetName();
      const bool asked = names.empty() ||
        (name && std::find(names.begin(), names.end(), std::string(name)) != names.end());
      if (!asked)
      {
        return;
      }
      const char* values = array->GetNumberOfComponents() == 1 ? " values" : " tuples";
      warnings.push_back(what + ": its " + (points ? "point" : "cell") + "-data array " +
        ArrayLabel(array) + " has " + std::to_string(count) + values + " for " +
        std::to_string(needed) + (points ? " points" : " cells") + ", so its" + values + " " +
        std::to_string(needed) + " to " + std::to_string(count - 1) +
        " (counted from 0) belong to none and are not used");
    });
  return warnings;
}

namespace
{
/// Whether every value of a connectivity array lies in 0 .. points - 1: one pass over the values
/// each time (vtkDataArray::GetRange keeps a range until the array itself is marked modified,
/// which InsertNextCell and ReplaceCellAtId do not do: a bad id put in after a good run passed).
template<class Values>
bool AllPointIds(const Values* values, vtkIdType count, vtkIdType points)
{
  bool inside = true;
  for (vtkIdType k = 0; k < count; ++k)
  {
    inside &= values[k] >= 0 && values[k] < points;
  }
  return inside;
}

/// The first point id of cells outside 0 .. points - 1, as (cell, id), or (-1, 0) when every id
/// is a point's. A pass over the connectivity answers for most inputs without a walk over cells.
std::pair<vtkIdType, vtkIdType> FirstMissingPoint(vtkCellArray* cells, vtkIdType points)
{
  const vtkIdType count = cells->GetNumberOfConnectivityIds();
  const bool allPoints = cells->IsStorage64Bit()
    ? AllPointIds(cells->GetConnectivityArray64()->GetPointer(0), count, points)
    : AllPointIds(cells->GetConnectivityArray32()->GetPointer(0), count, points);
  if (allPoints)
  {
    return { -1, 0 };
  }
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < cells->GetNumberOfCells(); ++c)
  {
    cells->GetCellAtId(c, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      if (ids->GetId(k) < 0 || ids->GetId(k) >= points)
      {
        return { c, ids->GetId(k) };
      }
    }
  }
  return { -1, 0 };
}
} // namespace

void CheckCellPointIds(vtkDataSet* data, const std::string& what)
{
  std::vector<vtkCellArray*> kinds; // in the order of their cells' ids
  if (auto* poly = vtkPolyData::SafeDownCast(data))
  {
    kinds = { poly->GetVerts(), poly->GetLines(), poly->GetPolys(), poly->GetStrips() };
  }
  else if (auto* grid = vtkUnstructuredGrid::SafeDownCast(data))
  {
    kinds = { grid->GetCells() };
  }
  const vtkIdType points = data->GetNumberOfPoints();
  vtkIdType before = 0; // cells of the kinds before this one
  for (vtkCellArray* cells : kinds)
  {
    if (!cells)
    {
      continue;
    }
    const auto [cell, id] = FirstMissingPoint(cells, points);
    if (cell >= 0)
    {
      throw tessera::InputError(what + ": cell " + std::to_string(before + cell) +
        " refers to point " + std::to_string(id) + ", but " +
        (points == 0 ? std::string("there are no points")
                     : "the points are 0 to " + std::to_string(points - 1)));
    }
    before += cells->GetNumberOfCells();
  }
}

void CheckArraysAndCellPointIds(vtkDataSet* data, const std::string& what)
{
  CheckAttributeLengths(data, what);
  CheckCellPointIds(data, what);
}

void RequestWholeInputs(vtkInformationVector** inputVector, int firstPort, int lastPort)
{
  for (int port = firstPort; port <= lastPort; ++port)
  {
    for (int k = 0; k < inputVector[port]->GetNumberOfInformationObjects(); ++k)
    {
      AskForTheWhole(inputVector[port]->GetInformationObject(k));
    }
  }
}

namespace
{
/// Whether an output's request holds key above value (its piece's number, or its number of pieces).
bool AnyRequestAbove(vtkInformationVector* outputVector, vtkInformationIntegerKey* key, int value)
{
  for (int k = 0; k < outputVector->GetNumberOfInformationObjects(); ++k)
  {
    vtkInformation* info = outputVector->GetInformationObject(k);
    if (info->Has(key) && info->Get(key) > value)
    {
      return true;
    }
  }
  return false;
}
} // namespace

bool IsPieceOfMany(vtkInformationVector* outputVector)
{
  return AnyRequestAbove(
    outputVector, vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
}

bool MakesOutput(vtkInformationVector* outputVector)
{
  return !AnyRequestAbove(outputVector, vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
}

vtkSmartPointer<vtkPointSet> InputPoints(vtkDataObject* data, std::vector<std::string>& warnings)
{
  if (auto* points = vtkPointSet::SafeDownCast(data))
  {
    CheckAttributeLengths(points, "the input");
    for (std::string& warning : LongAttributeWarnings(points, "the input", true))
    {
      warnings.push_back(std::move(warning));
    }
    // One vertex per point (ParaView's Merge Blocks of a GDAL point layer): the vertices'
    // attributes are the points'.
    const std::vector<std::string> cellArrays = UncarriedCellArrays(points);
    vtkSmartPointer<vtkPointSet> carried = VertexArraysAsPointData(points, cellArrays);
    const std::string hidden = HiddenCellArraysProblem(points, "the input");
    if (!hidden.empty() && points->GetNumberOfPoints() > 0)
    {
      warnings.push_back(hidden);
    }
    if (carried == points && !cellArrays.empty() && points->GetNumberOfPoints() > 0)
    {
      warnings.push_back("the input's cell-data arrays (" + QuotedNames(cellArrays) +
        ") are not carried: its cells are not one vertex per point, so they are no point's");
    }
    return carried;
  }
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(data))
  {
    std::map<std::string, std::string> dropped;
    vtkSmartPointer<vtkPolyData> joined = MergedPoints(composite, {}, &dropped);
    for (const auto& [name, problem] : dropped)
    {
      warnings.push_back(
        name.empty() ? problem : "the array '" + name + "' is not carried: " + problem);
    }
    return joined;
  }
  throw tessera::InputError(std::string("the input is ") +
    (data ? std::string("a ") + data->GetClassName() : std::string("missing")) +
    ", not points: a vtkPointSet (vtkPolyData, vtkUnstructuredGrid, ...) or a composite data set "
    "of them is needed");
}

std::vector<std::string> HiddenVertexArrayWarnings(vtkDataObject* data,
  const std::vector<std::string>& names,
  const std::string& what)
{
  std::vector<std::pair<vtkPointSet*, std::string>> sets;
  if (auto* points = vtkPointSet::SafeDownCast(data))
  {
    sets.emplace_back(points, what);
  }
  else if (auto* composite = vtkCompositeDataSet::SafeDownCast(data))
  {
    for (const PointLeaf& leaf : PointLeaves(composite))
    {
      sets.emplace_back(leaf.Set, leaf.Label + " of " + what);
    }
  }
  std::vector<std::string> warnings;
  for (const auto& [set, label] : sets)
  {
    const std::vector<std::string> hidden = HiddenCellArrays(set, names);
    if (!hidden.empty())
    {
      warnings.push_back("the cell-data array(s) " + QuotedNames(hidden) + " of " + label +
        " are not used: point-data arrays of the same names are");
    }
  }
  return warnings;
}

vtkSmartPointer<vtkPointSet> VertexArraysAsPointData(vtkPointSet* points,
  const std::vector<std::string>& names)
{
  std::vector<std::string> wanted;
  for (const std::string& name : UncarriedCellArrays(points))
  {
    if (std::find(names.begin(), names.end(), name) != names.end())
    {
      wanted.push_back(name);
    }
  }
  const std::vector<vtkIdType> cellOf =
    wanted.empty() ? std::vector<vtkIdType>() : VertexCellOfPoint(points);
  if (cellOf.empty())
  {
    return points;
  }
  return WithVertexAttributes(points, cellOf, wanted);
}

namespace
{

/// The leaves' points, in block order.
vtkSmartPointer<vtkPoints> JoinedLeafPoints(const std::vector<PointLeaf>& leaves)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  for (const PointLeaf& leaf : leaves)
  {
    for (vtkIdType p = 0; p < leaf.Set->GetNumberOfPoints(); ++p)
    {
      points->InsertNextPoint(leaf.Set->GetPoint(p));
    }
  }
  return points;
}

/// The names of every leaf's arrays, in the order first met; the problems of arrays that cannot
/// be joined by name go to dropped[""] (when given).
std::vector<std::string> AllLeafArrayNames(const std::vector<PointLeaf>& leaves,
  std::map<std::string, std::string>* dropped)
{
  std::vector<std::string> names;
  for (const PointLeaf& leaf : leaves)
  {
    // Cell data of any leaf: a leaf whose cells are not one vertex per point (a multipoint
    // feature) cannot carry it, and JoinProblem says so rather than it being left out unsaid.
    for (const std::string& name : ArrayNames(leaf.Set))
    {
      if (std::find(names.begin(), names.end(), name) == names.end())
      {
        names.push_back(name);
      }
    }
    for (const std::string& problem :
      { UnnamedArraysProblem(leaf), HiddenCellArraysProblem(leaf.Set, leaf.Label) })
    {
      if (dropped && !problem.empty())
      {
        std::string& all = (*dropped)[std::string()];
        all += (all.empty() ? "" : "; ") + problem;
      }
    }
  }
  return names;
}

/// The leaves' arrays of one name (JoinProblem found none missing or of another type) joined
/// into one, a tuple per point in block order; null for no leaves.
vtkSmartPointer<vtkAbstractArray> JoinedLeafArray(const std::vector<PointLeaf>& leaves,
  const std::string& name)
{
  vtkSmartPointer<vtkAbstractArray> joined;
  for (const PointLeaf& leaf : leaves)
  {
    const LeafArray found = FindLeafArray(leaf.Set, name, leaf.CellOf);
    if (!joined)
    {
      joined.TakeReference(found.Array->NewInstance());
      joined->SetName(name.c_str());
      joined->SetNumberOfComponents(found.Array->GetNumberOfComponents());
    }
    for (vtkIdType p = 0; p < leaf.Set->GetNumberOfPoints(); ++p)
    {
      joined->InsertNextTuple(found.Row(p), found.Array);
    }
  }
  return joined;
}

} // namespace

vtkSmartPointer<vtkPolyData> MergedPoints(vtkCompositeDataSet* composite,
  const std::vector<std::string>& arrays,
  std::map<std::string, std::string>* dropped)
{
  const std::vector<PointLeaf> leaves = PointLeaves(composite);
  auto merged = vtkSmartPointer<vtkPolyData>::New();
  merged->SetPoints(JoinedLeafPoints(leaves));
  const std::vector<std::string> names =
    arrays.empty() ? AllLeafArrayNames(leaves, dropped) : arrays;
  for (const std::string& name : names)
  {
    const std::string problem = JoinProblem(leaves, name);
    if (!problem.empty())
    {
      if (!dropped)
      {
        throw tessera::InputError(problem);
      }
      dropped->emplace(name, problem);
      continue;
    }
    if (vtkSmartPointer<vtkAbstractArray> joined = JoinedLeafArray(leaves, name))
    {
      merged->GetPointData()->AddArray(joined);
    }
  }
  return merged;
}

namespace
{
/// The warning for the cells of a window/catchment input that are not rings (what names the
/// input), or empty when there are none.
std::string SkippedCellsWarning(const Rings& rings, const char* what)
{
  std::string text;
  if (rings.SkippedCells > 0)
  {
    text = std::to_string(rings.SkippedCells) + " cell(s) of the " + what +
      " are not polygons or closed polylines, nor lines that join end to end into closed rings, "
      "and were ignored (the first is " +
      rings.FirstSkipped + ").";
  }
  if (!rings.SkippedBlocks.empty())
  {
    text += std::string(text.empty() ? "" : " ") + std::to_string(rings.SkippedBlocks.size()) +
      " block(s) of the " + what +
      " are not vtkPolyData and were not read (extract their surface first): " +
      ListNames(rings.SkippedBlocks.size(), [&](std::size_t k) { return rings.SkippedBlocks[k]; }) +
      ".";
  }
  return text;
}

/// Leaves out the pairs of rings that are a hole and the island that fills it exactly (core
/// identical_rings.h: by the even-odd rule each pair cancels, and the region is the union of the
/// island's feature and the hole's); returns the warning that names them by their sources, or "".
/// (Some ring always stays: a hole lies inside one.)
std::string CancelIdenticalRings(Rings& rings, const char* what)
{
  const auto pairs = tessera::IdenticalRingPairs(rings.Offsets, rings.Vertices);
  if (pairs.empty())
  {
    return std::string();
  }
  const std::string named = ListNames(pairs.size(),
    [&](std::size_t k)
    { return rings.Sources[pairs[k].first] + " and " + rings.Sources[pairs[k].second]; });
  std::vector<char> cancelled(rings.Sources.size(), 0);
  for (const auto& [r, s] : pairs)
  {
    cancelled[r] = cancelled[s] = 1;
  }
  Rings kept = rings; // (what is not per ring: skipped cells and blocks, block names)
  kept.Offsets.assign(1, 0);
  kept.Vertices.clear();
  kept.Sources.clear();
  kept.Blocks.clear();
  for (std::size_t r = 0; r < cancelled.size(); ++r)
  {
    if (!cancelled[r])
    {
      kept.Vertices.insert(kept.Vertices.end(),
        rings.Vertices.begin() + std::ptrdiff_t(rings.Offsets[r]),
        rings.Vertices.begin() + std::ptrdiff_t(rings.Offsets[r + 1]));
      kept.Offsets.push_back(kept.Vertices.size());
      kept.Sources.push_back(rings.Sources[r]);
      kept.Blocks.push_back(rings.Blocks[r]);
    }
  }
  rings = std::move(kept);
  return std::to_string(pairs.size()) + " hole(s) of the " + what +
    " are filled exactly by a ring of their own (an enclave given as a hole and as a polygon): by "
    "the even-odd rule the two rings cancel, so the enclave is part of the region, joined to what "
    "surrounds it (the rings: " +
    named + ").";
}

/// Where data spans z but lies flat in x or y (drawn in a vertical plane), why its rings come out
/// as lines: only x and y are read (a window in the x-z plane was refused as rings of "fewer than
/// 3 distinct vertices", with no word of z). "" otherwise.
std::string VerticalPlaneWarning(vtkDataObject* data, const char* what)
{
  double bounds[6];
  if (!DataBounds(data, bounds) || !(bounds[5] > bounds[4]) ||
    (bounds[1] > bounds[0] && bounds[3] > bounds[2]))
  {
    return std::string();
  }
  return std::string("the ") + what + " lies in a vertical plane (x from " +
    tessera::NumberText(bounds[0]) + " to " + tessera::NumberText(bounds[1]) + ", y from " +
    tessera::NumberText(bounds[2]) + " to " + tessera::NumberText(bounds[3]) + ", z from " +
    tessera::NumberText(bounds[4]) + " to " + tessera::NumberText(bounds[5]) +
    "): only x and y are read, so its rings are flat; give it in the x-y plane";
}
} // namespace

const char* const ExtractSurfaceHint =
  "extract its surface first (ParaView's Extract Surface, vtkGeometryFilter)";

Rings ReadPolygonRings(vtkDataObject* data, const char* what, std::vector<std::string>& warnings)
{
  Rings rings;
  if (auto* poly = vtkPolyData::SafeDownCast(data))
  {
    CheckCellPointIds(poly, std::string("the ") + what);
    AppendPolygonRings(poly, std::string(), rings);
    rings.Blocks.resize(rings.Offsets.size() - 1, -1);
  }
  else if (auto* composite = vtkCompositeDataSet::SafeDownCast(data))
  {
    auto iter = vtk::TakeSmartPointer(composite->NewIterator());
    const BlockLabels labels(composite);
    for (iter->InitTraversal(); !iter->IsDoneWithTraversal(); iter->GoToNextItem())
    {
      if (auto* block = vtkPolyData::SafeDownCast(iter->GetCurrentDataObject()))
      {
        const std::int64_t flat = iter->GetCurrentFlatIndex();
        const std::string label = labels.Of(iter);
        CheckCellPointIds(block, label + " of the " + what);
        AppendPolygonRings(block, label + " ", rings);
        rings.Blocks.resize(rings.Offsets.size() - 1, flat);
        rings.BlockNames.emplace(flat, label);
      }
      else if (auto* other = vtkDataSet::SafeDownCast(iter->GetCurrentDataObject()))
      {
        if (other->GetNumberOfCells() > 0)
        {
          rings.SkippedBlocks.push_back(labels.Of(iter) + " (" + other->GetClassName() + ")");
        }
      }
    }
  }
  if (rings.Offsets.size() < 2)
  {
    const std::string skipped = SkippedCellsWarning(rings, "input");
    const bool otherSet = vtkDataSet::SafeDownCast(data) && !vtkPolyData::SafeDownCast(data);
    throw tessera::InputError(std::string("the window/catchment input (") +
      (data ? data->GetClassName() : "nothing") + ") holds no polygon" +
      (otherSet ? std::string(" that is read: only vtkPolyData (or a composite data set of it) "
                              "is; ") +
            ExtractSurfaceHint
                : std::string()) +
      (skipped.empty() ? std::string() : ": " + skipped));
  }
  for (const std::string& warning : { SkippedCellsWarning(rings, what),
         CancelIdenticalRings(rings, what),
         VerticalPlaneWarning(data, what) })
  {
    if (!warning.empty())
    {
      warnings.push_back(warning);
    }
  }
  return rings;
}

namespace
{
std::string PointText(const tessera::Point2& p)
{
  return "(" + tessera::NumberText(p.x) + ", " + tessera::NumberText(p.y) + ")";
}

/// "ring 2 segment 5 runs from (3, 1) to (4, 1)": segment k from the ring's vertex k to k + 1.
std::string SegmentPlace(const Rings& rings, const tessera::RingError::Segment& segment)
{
  const std::string name = segment.Name();
  if (segment.Ring + 1 >= rings.Offsets.size())
  {
    return name + " (not a ring read)";
  }
  const std::size_t begin = rings.Offsets[segment.Ring];
  const std::size_t count = rings.Offsets[segment.Ring + 1] - begin;
  if (segment.Index >= count)
  {
    return name + " (not a segment of the ring read)";
  }
  const std::size_t next = segment.Index + 1 == count ? 0 : segment.Index + 1;
  return name + " runs from " + PointText(rings.Vertices[begin + segment.Index]) + " to " +
    PointText(rings.Vertices[begin + next]);
}
} // namespace

tessera::InputError WithRingSources(const tessera::RingError& error,
  const Rings& rings,
  const char* what)
{
  std::string text;
  for (const std::size_t r : error.Rings)
  {
    const std::string source = r < rings.Sources.size() ? rings.Sources[r] : "unknown";
    text += (text.empty() ? "" : "; ") + std::string("ring ") + std::to_string(r) + " is " +
      source + " of the " + what;
  }
  std::set<std::pair<std::size_t, std::size_t>> placed; // (a segment named twice, said once)
  for (const tessera::RingError::Segment& segment : error.Segments)
  {
    if (placed.insert({ segment.Ring, segment.Index }).second)
    {
      text += "; " + SegmentPlace(rings, segment);
    }
  }
  return tessera::InputError(std::string(error.what()) + " (" + text + ")");
}

double OrientAnticlockwise(std::vector<tessera::Point2>& polygon)
{
  const double area = tessera::CompensatedPolygonArea(polygon.data(), polygon.size());
  if (area < 0.0)
  {
    std::reverse(polygon.begin(), polygon.end());
  }
  return std::abs(area);
}

namespace
{
/// The first of name + "_input", name + "_input_2", ... that no array of data has: an input with
/// both "Area" and "Area_input" keeps both.
std::string FreeInputName(vtkFieldData* data, const std::string& name)
{
  std::string candidate = name + "_input";
  for (int k = 2; data->GetAbstractArray(candidate.c_str()) != nullptr; ++k)
  {
    candidate = name + "_input_" + std::to_string(k);
  }
  return candidate;
}

/// The field data arrays AddUnusedPointIds writes.
const std::vector<const char*>& UnusedPointIdNames()
{
  static const std::vector<const char*> names{
    "RejectedPointIds", "DuplicatePointIds", "DuplicateOfPointIds"
  };
  return names;
}

} // namespace

RenamedArrays RenameArraysNamed(vtkFieldData* data, const std::vector<const char*>& own, bool copy)
{
  RenamedArrays renamed;
  for (const char* name : own)
  {
    vtkAbstractArray* array = data->GetAbstractArray(name);
    if (!array)
    {
      continue;
    }
    const std::string newName = FreeInputName(data, name);
    if (copy)
    {
      vtkSmartPointer<vtkAbstractArray> renamedCopy =
        vtkSmartPointer<vtkAbstractArray>::Take(array->NewInstance());
      renamedCopy->DeepCopy(array);
      renamedCopy->SetName(newName.c_str());
      data->RemoveArray(name);
      data->AddArray(renamedCopy);
    }
    else
    {
      array->SetName(newName.c_str());
    }
    renamed.emplace_back(name, newName);
  }
  return renamed;
}

std::string RenamedArraysWarning(const RenamedArrays& renamed,
  const char* kind,
  const char* where,
  const char* ownKind)
{
  std::string message;
  for (const auto& [from, to] : renamed)
  {
    message += std::string(message.empty() ? "" : "; ") + "input " + kind + " array '" + from +
      "' is passed to " + where + " as '" + to + "' ('" + from + "' is this filter's own " +
      ownKind + " array)";
  }
  return message;
}

RenamedArrays AddUnusedPointIds(vtkDataObject* data,
  const std::vector<std::int32_t>& rejected,
  const std::vector<std::pair<std::int32_t, std::int32_t>>& duplicates)
{
  const RenamedArrays renamed = RenameArraysNamed(data->GetFieldData(), UnusedPointIdNames(), true);
  AddIdFieldArray(data, UnusedPointIdNames()[0], rejected);
  AddDuplicatePointIds(data, duplicates);
  return renamed;
}

void AddDuplicatePointIds(vtkDataObject* data,
  const std::vector<std::pair<std::int32_t, std::int32_t>>& duplicates)
{
  std::vector<std::int32_t> copies, originals;
  for (const auto& [copy, original] : duplicates)
  {
    copies.push_back(copy);
    originals.push_back(original);
  }
  AddIdFieldArray(data, UnusedPointIdNames()[1], copies);
  AddIdFieldArray(data, UnusedPointIdNames()[2], originals);
}

namespace
{

/// The first 20 rejected ids, as ListNames gives them.
std::string RejectedIdsText(const std::vector<std::int32_t>& rejected)
{
  return tessera::ListNames(
    rejected.size(), [&](std::size_t k) { return std::to_string(rejected[k]); });
}

/// The field data arrays that list unused points, some of them rejected or some duplicates:
/// "array RejectedPointIds", "arrays DuplicatePointIds and DuplicateOfPointIds", or all three.
std::string UnusedIdArraysText(bool rejected, bool duplicates)
{
  if (!duplicates)
  {
    return "array RejectedPointIds";
  }
  return std::string("arrays ") + (rejected ? "RejectedPointIds, " : "") +
    "DuplicatePointIds and DuplicateOfPointIds";
}

/// The warning for a window (its bounding box) that holds none of the points (`rejected` all of
/// them), so that there is no `what` ("tile"), naming the window's box and the points' (a
/// ParaView user saw only a count of rejected points and an empty output), with a hint on units
/// and order where the boxes do not meet, and the first 20 ids; empty where some point was taken,
/// or there is none.
std::string NoPointInWindowWarning(const tessera::Box2& window,
  vtkPoints* points,
  const std::vector<std::int32_t>& rejected,
  const char* what)
{
  if (!points || points->GetNumberOfPoints() == 0 ||
    rejected.size() != static_cast<std::size_t>(points->GetNumberOfPoints()))
  {
    return std::string();
  }
  const tessera::Box2 box = BoundsOfPoints(points);
  const bool apart = !box.Meets(window);
  return "no point lies inside the window (" + BoxText(window) + "), so there is no " + what +
    ": the points span " + BoxText(box) +
    (apart ? " (is the window in the points' units, WindowBounds in the order xmin, xmax, ymin, "
             "ymax?)"
           : " (the boxes overlap, but each point lies outside the window or on its boundary)") +
    "; all " + std::to_string(rejected.size()) +
    " point(s) are in the field data array RejectedPointIds: " + RejectedIdsText(rejected) + ".";
}

/// For points stored as float: the float's step at their largest x or y, within which points
/// given as doubles became one when stored (a trial's UTM points, 1 mm apart at 5e6, lost 382 as
/// duplicates without a word of why). Empty for other points.
std::string FloatStorageNote(vtkPoints* points)
{
  if (!points || points->GetDataType() != VTK_FLOAT || points->GetNumberOfPoints() == 0)
  {
    return std::string();
  }
  double bounds[6];
  points->GetBounds(bounds);
  const double largest = std::max(
    { std::fabs(bounds[0]), std::fabs(bounds[1]), std::fabs(bounds[2]), std::fabs(bounds[3]) });
  const float stored = static_cast<float>(largest);
  const double step = static_cast<double>(std::nextafter(stored, HUGE_VALF)) - stored;
  return " The points are stored as float, whose step at coordinates of " +
    tessera::NumberText(largest) + " is " + tessera::NumberText(step) +
    ": points that near each other may have become one when they were stored (store them as "
    "double: vtkPoints::SetDataTypeToDouble before they are set, or a reader's double-precision "
    "option).";
}

/// The warning for points a tessellation filter did not use (`rejected` outside the window,
/// `duplicates` exact copies with the point each copies), saying they were not `verb` ("used",
/// "triangulated"), where their ids are, and the first 20 of each (a count of none is left out);
/// empty when every point was used. With duplicates among input `points` stored as float, it also
/// says the float's step at their coordinates, within which points became one when stored.
std::string UnusedPointsWarning(const std::vector<std::int32_t>& rejected,
  const std::vector<std::pair<std::int32_t, std::int32_t>>& duplicates,
  const char* verb,
  vtkPoints* points)
{
  if (rejected.empty() && duplicates.empty())
  {
    return std::string();
  }
  // (the first ids too: a trial's script had only the counts, and had to read the arrays; a
  // count of 0 is left out, as "and 0 exact duplicate(s)" said nothing)
  std::ostringstream text;
  if (!rejected.empty())
  {
    text << rejected.size() << " point(s) outside the window or on its boundary";
  }
  if (!duplicates.empty())
  {
    text << (rejected.empty() ? "" : " and ") << duplicates.size()
         << " exact duplicate(s) (the same x and y; z is not used)";
  }
  text << " were not " << verb << "; their ids are in the field data "
       << UnusedIdArraysText(!rejected.empty(), !duplicates.empty());
  if (!rejected.empty())
  {
    text << "; outside: point(s) " << RejectedIdsText(rejected);
  }
  if (!duplicates.empty())
  {
    text << "; duplicates: " << tessera::DuplicatePairNames(duplicates);
  }
  return text.str() + "." + (duplicates.empty() ? std::string() : FloatStorageNote(points));
}

} // namespace

std::string NoPointsWarning(const std::string& what)
{
  return "the input has no points: no " + what + " (does the filter before it give none?)";
}

std::string PointsNotUsedWarning(const tessera::Box2& window,
  const std::vector<std::int32_t>& rejected,
  const std::vector<std::pair<std::int32_t, std::int32_t>>& duplicates,
  const char* verb,
  const char* what,
  vtkPoints* points)
{
  const std::string none = NoPointInWindowWarning(window, points, rejected, what);
  return none.empty() ? UnusedPointsWarning(rejected, duplicates, verb, points) : none;
}

} // namespace tessera_vtk
