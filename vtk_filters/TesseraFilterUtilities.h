// Conversions shared by the Tessera filters: VTK data to core types and back. Private to the
// module (not wrapped, not installed): core types may appear here, never in a filter's header.
#ifndef TesseraFilterUtilities_h
#define TesseraFilterUtilities_h

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include "errors.h"
#include "geometry.h"
#include "large_pages.h"
#include "window.h"

#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

class vtkAbstractArray;
class vtkAlgorithm;
class vtkAlgorithmOutput;
class vtkCellArray;
class vtkCompositeDataIterator;
class vtkCompositeDataSet;
class vtkDataSet;
class vtkInformationVector;
class vtkDataObject;
class vtkFieldData;
class vtkIdList;
class vtkPoints;
class vtkPointSet;
class vtkPolyData;

namespace tessera_vtk
{

/// x, y of every point (z ignored), as they are (NaN and infinities included: for a caller whose
/// core check names the points better); 64-bit integer points that no double holds exactly
/// (some beyond 2^53) are a tessera::InputError naming the first.
std::vector<tessera::Point2> CopyPoints2D(vtkPoints* points);

/// CopyPoints2D, throwing tessera::InputError naming the first point with a NaN or infinite x or y
/// (JoinedPointName: with its block when the points were joined from joinedFrom's blocks).
std::vector<tessera::Point2> ReadPoints2D(vtkPoints* points, vtkDataObject* joinedFrom = nullptr);

/// "point ID" of the points InputPoints made of data, followed for a composite data set by the
/// block it came from: "point 6 (point 2 of block 1 (composite index 2))".
std::string JoinedPointName(vtkDataObject* data, vtkIdType id);

/// A core progress callback for a stage of algorithm's run, from fraction `from` to `to` of it:
/// it updates the algorithm's progress and returns false once its AbortExecute is set (a
/// progress observer asked it to stop; the core then throws tessera::Cancelled).
std::function<bool(double)> StageProgress(vtkAlgorithm* algorithm, double from, double to);

/// Sets algorithm's progress to fraction and throws tessera::Cancelled when its AbortExecute is
/// set: between stages of a run, where nothing is left half made.
void ProgressOrStop(vtkAlgorithm* algorithm, double fraction);

/// Whether an exception caught in a RequestData is a stop that a progress observer asked for
/// (tessera::Cancelled): the outputs are emptied as for an error, but no error is reported
/// (tesseraErrorOrStopMacro).
bool IsStop(const std::exception& e);

/// The data of an upstream connection, brought up to date (for a RequestInformation that needs
/// the input's data: the areal average's time steps, the ridge grouping's image extent).
vtkDataObject* UpdatedData(vtkAlgorithmOutput* connection);

/// How messages name a composite data set's leaves: by their path in the tree as a script builds
/// it ("block 1", "block 0/2": SetBlock's indices), with the composite (flat) index that
/// ParaView's Multiblock Inspector shows and the block's name when it has one:
/// "block 1 (composite index 2, 'Gauges')".
class BlockLabels
{
public:
  explicit BlockLabels(vtkCompositeDataSet* data);
  std::string Of(vtkCompositeDataIterator* it) const;

private:
  std::map<vtkDataObject*, std::string> Paths;
};

/// Throws tessera::InputError (naming `what` and the array) when a point-data array of data has
/// fewer values than it has points, or a cell-data array fewer than cells: the filters copy them
/// by point and cell id, and a short one was read past its end (a crash, or garbage in the tiles).
void CheckAttributeLengths(vtkDataSet* data, const std::string& what);

/// Warnings naming (with `what`) each point-data array of data with more values than it has points
/// (pointData true), or each cell-data array with more than cells (pointData false: the data a
/// filter carries); with `names` given, only arrays of those names.
/// The values past the last point or cell belong to none: the filters copy by id and never read
/// them (VTK's vtkDataSet::CheckAttributes warns alike). Such an array is often a mismatch.
std::vector<std::string> LongAttributeWarnings(vtkDataSet* data,
  const std::string& what,
  bool pointData,
  const std::vector<std::string>& names = {});

/// Throws tessera::InputError (naming `what`, the cell and the id) when a cell of data refers to
/// a point it does not have: an id below 0 or not below its number of points, as in a polydata
/// with cells and no points. VTK reads such an id past the end of the points without a check: a
/// window triangle with point id 99 of 4 clipped to a wrong area, and cells without points
/// crashed. Checks the explicit cells of vtkPolyData and vtkUnstructuredGrid (other point sets'
/// cells are implicit in their dimensions).
void CheckCellPointIds(vtkDataSet* data, const std::string& what);

/// CheckAttributeLengths and then CheckCellPointIds: for data whose arrays a filter copies by id
/// and whose cells it reads.
void CheckArraysAndCellPointIds(vtkDataSet* data, const std::string& what);

/// An array as messages name it: "'Area'", or "without a name".
std::string ArrayLabel(vtkAbstractArray* array);

/// The points of every vtkPointSet leaf of a composite data set, in the leaves' order, as one
/// vtkPolyData (points only, no cells), with their arrays joined over the leaves. A leaf whose
/// cells are one vertex per point (a feature of vtkGDALVectorReader's point layer: its attributes
/// are cell data) gives its vertices' cell-data arrays as its points' (where it has no point-data
/// array of that name).
/// The arrays named in `arrays` (empty: every array some leaf has) are joined where every leaf
/// with points has them in one type and number of components. One that cannot be joined is left
/// out, with why (which leaf lacks it, or holds what) in (*dropped)[name]; without `dropped`, it is
/// an InputError saying why. With `arrays` empty, the leaves' unnamed point-data arrays (which
/// cannot be joined by name) are named in (*dropped)[""]. Throws tessera::InputError naming a leaf
/// that is not a point set, or whose arrays are short (CheckAttributeLengths).
vtkSmartPointer<vtkPolyData> MergedPoints(vtkCompositeDataSet* data,
  const std::vector<std::string>& arrays,
  std::map<std::string, std::string>* dropped);

/// A point filter's input as one point set:
/// - a vtkPointSet itself, or, when its cells are one vertex per point and carry cell data (a GDAL
///   point layer after ParaView's Merge Blocks), its points with those attributes as point data
///   (ids kept); cell data of other cells is not carried, and a line in `warnings` says so;
/// - a composite data set's points joined by MergedPoints with all their arrays (so that a point
///   layer read by vtkGDALVectorReader, a block per feature, is one set of points, not a
///   tessellation per point); arrays that cannot be joined get a line each in `warnings`.
/// Throws tessera::InputError naming the type of any other input (the filters take every type at
/// their port and check it here, so that a wrong one empties their outputs: the pipeline's own
/// type check stops before RequestData and left the last results in place), and for short
/// attribute arrays (CheckAttributeLengths).
vtkSmartPointer<vtkPointSet> InputPoints(vtkDataObject* data, std::vector<std::string>& warnings);

/// Lines naming, for a point set or each block of a composite data set of them (`what`: how the
/// messages call the input, e.g. "the gauges (input 0)"), the cell-data arrays among `names`
/// that a point-data array of the same name hides: the point data's is the one used.
std::vector<std::string> HiddenVertexArrayWarnings(vtkDataObject* data,
  const std::vector<std::string>& names,
  const std::string& what);

/// points itself, or, when its cells are one vertex per point and some of the arrays `names` are
/// its vertices' cell data only, a shallow copy with those given to its points as point data.
vtkSmartPointer<vtkPointSet> VertexArraysAsPointData(vtkPointSet* points,
  const std::vector<std::string>& names);

/// Asks every connection of input ports firstPort .. lastPort for the whole data set: piece 0 of
/// 1, no ghost levels. A tessellation, a triangulation, a grouping or a fitted projection of one
/// piece's points is not that of all the points (ParaView under MPI asks each process for a piece,
/// and each tessellated its own: tiles overlapping, their areas summing to twice the window's), so
/// every process reads the whole input and only the first piece makes the output (MakesOutput).
/// A filter's RequestUpdateExtent calls this instead of its superclass's, whose requests (the
/// output's piece, EXACT_EXTENT) are those it replaces.
void RequestWholeInputs(vtkInformationVector** inputVector, int firstPort, int lastPort);

/// False when an output's requested piece is not the first: that process leaves the outputs empty.
bool MakesOutput(vtkInformationVector* outputVector);

/// True when an output is asked for one piece of several (a process's piece under MPI).
bool IsPieceOfMany(vtkInformationVector* outputVector);

/// The window a filter works in: the rectangle `bounds` (xmin, xmax, ymin, ymax) when it is not
/// empty, intersected with `constraints` (a, b, c triples: a*x + b*y + c < 0); with neither, the
/// bounding box of the points padded on every side by `padding` times its larger side (a unit
/// square around a single point or a cloud of identical points; [-1, 1]^2 with no point). A side
/// that rounding would leave on the points (a padding below their coordinates' ulp) moves out to
/// the next double, so every point stays strictly inside. Throws tessera::InputError for a NaN
/// bound and, with needArea (tiles, whose areas would overflow), for a window so large (a huge
/// padding or bounds) that its area overflows.
tessera::Window ChooseWindow(const double bounds[4],
  const std::vector<double>& constraints,
  double padding,
  const std::vector<tessera::Point2>& points,
  bool needArea = true);

/// ChooseWindow, after the EmptyBoundsWarning (if there is one) given as the filter's warning:
/// before the window is made, since an empty WindowBounds is ignored and a window of the
/// constraints alone may then be refused, which the warning explains.
tessera::Window ChooseWindowWithWarning(vtkAlgorithm* filter,
  const double bounds[4],
  const std::vector<double>& constraints,
  double padding,
  const std::vector<tessera::Point2>& points,
  bool needArea);

/// The window cut down to the points' bounding box padded by its larger side (by 1 or the
/// coordinates' size for points without extent): for a triangulation the window only decides
/// which points are used, and the box holds every point strictly, so the same points are used. A
/// window of coordinates far larger than the points' (WindowBounds of +-1e308) could not be
/// scaled into the predicates' exact range together with them, and was refused naming a point.
/// The window as it is when the cut cannot be made (no points, a box that overflows, or no point
/// inside the window: its error is then the window's own).
tessera::Window CutToPoints(tessera::Window window, const std::vector<tessera::Point2>& points);

/// A warning for WindowBounds set to an empty rectangle (xmin >= xmax or ymin >= ymax, most likely
/// arguments in another order, such as (xmin, ymin, xmax, ymax)), which ChooseWindow ignores;
/// empty when there is none. The default 0, 0, 0, 0 ("no rectangle") gives none. withConstraints:
/// whether window constraints are set (the window is then those alone).
std::string EmptyBoundsWarning(const double bounds[4], bool withConstraints);

/// Adds an id array (vtkIdTypeArray, one component) named `name` to the data object's field data.
void AddIdFieldArray(vtkDataObject* data, const char* name, const std::vector<std::int32_t>& ids);

/// The bounds of a data set or of a composite's blocks (xmin, xmax, ymin, ymax, zmin, zmax);
/// false when it has no points (or is neither).
bool DataBounds(vtkDataObject* data, double bounds[6]);

/// "x xmin .. xmax, y ymin .. ymax", for messages.
std::string BoxText(const tessera::Box2& box);

/// For a filter whose outputs are the input's kind (REQUEST_DATA_OBJECT): on every output port,
/// an instance of the composite's class when composite is given (the input's, the output kept
/// when it is one already), else a vtkPolyData.
void MakeCompositeOrPolyDataOutput(vtkCompositeDataSet* composite,
  vtkInformationVector* outputVector);

/// Moves the empty field-data arrays of data (and of each block of a composite) after the others,
/// keeping their order otherwise. ParaView lists no field data at all when the first array is
/// empty (it counts the field's tuples by its first array): the lists of rejected or duplicate
/// points, often empty, came first and hid vtkWindowClip's WindowArea and CoveredFraction.
void ListNonEmptyFieldArraysFirst(vtkDataObject* data);

/// Appends ring (count points, scaled by 2^-exponent) to points and, as one closed polyline (its
/// first point repeated last, as VTK closes a line), to lines: how the filters write a tile's
/// outline rings (core/piece_outlines.h).
void AppendClosedLine(const tessera::Point2* ring,
  std::size_t count,
  int exponent,
  vtkPoints* points,
  vtkCellArray* lines);

/// Polygon rings as flat arrays (ring r is Vertices[Offsets[r] .. Offsets[r+1])).
struct Rings
{
  std::vector<std::size_t> Offsets{ 0 };
  std::vector<tessera::Point2> Vertices;
  /// Cells that are not rings (vertices, strips, lines and open polylines that join into no
  /// closed ring): their number, and the first of them ("cell 7", or "block 2 cell 7" in a
  /// composite data set).
  std::size_t SkippedCells = 0;
  std::string FirstSkipped;
  /// Blocks of a composite input that are not vtkPolyData and hold cells (an unstructured grid of
  /// polygons): not read, and named ("block 1 (composite index 2) (vtkUnstructuredGrid)").
  std::vector<std::string> SkippedBlocks;
  /// Per ring, where it came from ("cell 2", "block 1 (composite index 2) cell 0", "a ring of
  /// joined line cells"), for errors about rings (WithRingSources).
  std::vector<std::string> Sources;
  /// Per ring, the flat index of the block it came from in a composite data set (-1 for a
  /// vtkPolyData input): vtkGDALVectorReader gives each feature a block of its own.
  std::vector<std::int64_t> Blocks;
  /// The blocks' names in messages (BlockLabels), by flat index.
  std::map<std::int64_t, std::string> BlockNames;
};

/// Whether a line cell's point ids (ids) close a ring of 3 or more points: the last point is the
/// first, by id or by x and y, as vtkGDALVectorReader gives a polygon's rings.
bool IsClosedLine(vtkDataSet* data, vtkIdList* ids);

/// "extract its surface first (ParaView's Extract Surface, vtkGeometryFilter)": how to make poly
/// data of another data set, for the errors of inputs that only vtkPolyData is read as.
extern const char* const ExtractSurfaceHint;

/// Every polygon, triangle and quad cell, and every closed polyline (last point = first, as
/// vtkGDALVectorReader gives polygon rings), of a vtkPolyData or of every vtkPolyData block of a
/// composite data set, as one ring each (x, y used); then, per block, the closed rings that its
/// line cells and open polylines form end to end (a contour, as vtkCutter or ParaView's Contour
/// gives it: core segment_rings.h, ends matched by coordinates; where four or six lines meet, as
/// at a saddle, they are paired by angle into rings that touch there). Other cells, and lines in no
/// closed ring (an open branch, a spur off a ring; a line of no length counts only where it lies
/// at no point of a joined ring), are counted in SkippedCells; blocks of another
/// type with cells are listed in SkippedBlocks, and both are said in a warning. Pairs of rings that
/// are a hole and the island that fills it exactly (an enclave given as a hole and as a polygon)
/// are left out, as by the even-odd rule they cancel (core identical_rings.h), with a warning
/// naming them. Warnings (what names the input: "window (input 1)") are appended to warnings.
/// Throws tessera::InputError when there is no ring (naming the input's type when it is a data set
/// other than vtkPolyData: only poly data is read).
Rings ReadPolygonRings(vtkDataObject* data, const char* what, std::vector<std::string>& warnings);

/// error's message followed by where its rings came from and where the segments it names run, in
/// the input's coordinates: "... (ring 2 is cell 4 of the window (input 1); ring 2 segment 5 runs
/// from (3, 1) to (4, 1))", one clause per ring and per segment; `what` names the input whose
/// rings were read.
tessera::InputError WithRingSources(const tessera::RingError& error,
  const Rings& rings,
  const char* what);

/// The core's (errors.h), under the name the filters have always used.
using tessera::ListNames;

/// The name of vtkGeographicProjection's field-data record of the projection it applied.
extern const char* const ProjectionRecordName;

/// Adds the record (ProjectionParameters::ToString) to the data object's field data as a one-value
/// string array named ProjectionRecordName.
void WriteProjectionRecord(vtkDataObject* data, const std::string& record);

/// The projection record of a data object's own field data, or "" when it has none.
std::string ReadProjectionRecord(vtkDataObject* data);

/// The projection record of a data object: its own, or else the one the leaves of a composite
/// carry (vtkGeographicProjection writes it on both); "" when there is none. Throws
/// tessera::InputError when leaves carry different ones. what names the input in that message.
std::string ProjectionRecordOf(vtkDataObject* data, const std::string& what);

/// Reverses a clockwise polygon; returns its (now non-negative) shoelace area.
double OrientAnticlockwise(std::vector<tessera::Point2>& polygon);

/// (input name, output name) of the input arrays a filter passes under another name, because it
/// writes an array of that name itself.
using RenamedArrays = std::vector<std::pair<std::string, std::string>>;

/// Renames the arrays of data named as one of `own` (the filter's own arrays, about to be added)
/// to the first of NAME_input, NAME_input_2, ... that data lacks, so that both reach the output:
/// adding the filter's array would replace the input's silently. With `copy`, each is replaced by a
/// renamed copy first (field data passed by the pipeline shares the input's array objects, which
/// must keep their names).
RenamedArrays RenameArraysNamed(vtkFieldData* data, const std::vector<const char*>& own, bool copy);

/// "input <kind> array 'X' is passed to <where> as 'X_input' ('X' is this filter's own <ownKind>
/// array)", one clause per renamed array.
std::string RenamedArraysWarning(const RenamedArrays& renamed,
  const char* kind,
  const char* where,
  const char* ownKind);

/// The field data arrays every tessellation filter writes for points it did not use:
/// `RejectedPointIds` (outside the window or on its boundary), `DuplicatePointIds` and
/// `DuplicateOfPointIds` (exact copies and the accepted point each one copies). An input field-data
/// array with one of these names is kept under another name (RenameArraysNamed); returns those
/// renamed.
RenamedArrays AddUnusedPointIds(vtkDataObject* data,
  const std::vector<std::int32_t>& rejected,
  const std::vector<std::pair<std::int32_t, std::int32_t>>& duplicates);

/// The field data arrays `DuplicatePointIds` and `DuplicateOfPointIds` of (copy, original) pairs of
/// points at one place (AddUnusedPointIds writes them; ridge grouping, which groups its copies,
/// writes them alone). Arrays of those names already there are replaced.
void AddDuplicatePointIds(vtkDataObject* data,
  const std::vector<std::pair<std::int32_t, std::int32_t>>& duplicates);

/// One warning for the points a tessellation filter did not use (`rejected` outside the window,
/// `duplicates` exact copies with the point each copies), empty when every point was used. Where
/// no point lies in the window (every one rejected), it names the window's bounding box and the
/// points', with a hint on units and order where the boxes do not meet, and the first 20 ids (a
/// ParaView user saw only a count and an empty output; a second warning, counting the same points
/// as outside, said nothing more), saying there is no `what` ("tile"). Else it says the points were
/// not `verb` ("used", "triangulated"), the field data arrays that list them, and the first 20 of
/// each kind (a count of none left out); with duplicates among input `points` stored as float, also
/// the float's step at their coordinates, within which points became one when stored.
std::string PointsNotUsedWarning(const tessera::Box2& window,
  const std::vector<std::int32_t>& rejected,
  const std::vector<std::pair<std::int32_t, std::int32_t>>& duplicates,
  const char* verb,
  const char* what,
  vtkPoints* points);

/// The warning for an input without points, whose output is then empty: "the input has no points:
/// no <what> (does the filter before it give none?)" (a ParaView user saw an empty output and no
/// message, where the filter before had failed or kept nothing).
std::string NoPointsWarning(const std::string& what);

/// Throws tessera::InputError unless value is one of the choices 0 .. names.size() - 1, naming
/// them: "Basis 5 is not one of 0 (InverseMultiquadric), 1 (Gaussian)". For the filters'
/// enumerated settings, which are set with vtkSetMacro: vtkSetClampMacro turned a wrong value into
/// another choice without a word (SetBasis(5) ran the Gaussian).
void CheckChoice(const char* property, int value, const std::vector<const char*>& names);

/// Sizes array to `tuples` tuples of `components` values, left unwritten. A large array (the
/// filters' outputs at 10^5 points and more) is allocated on huge pages (core large_pages.h: a
/// page fault per 2 MiB instead of per 4 KiB, which on a virtual machine halved the tiles
/// filter's time at 10^5 points) and handed to the array, which frees it.
template<class ArrayT>
void AllocateValues(ArrayT* array, vtkIdType tuples, int components = 1)
{
  using Value = typename ArrayT::ValueType;
  array->SetNumberOfComponents(components);
  const vtkIdType values = tuples * components;
  const std::size_t bytes = static_cast<std::size_t>(values) * sizeof(Value);
  if (bytes < tessera::LargePageBytes)
  {
    array->SetNumberOfTuples(tuples);
    return;
  }
  array->SetArray(
    static_cast<Value*>(tessera::AllocateLarge(bytes)), values, 0, ArrayT::VTK_DATA_ARRAY_FREE);
}

} // namespace tessera_vtk

/// What a filter's RequestData catch block returns once it has emptied its outputs: e.what()
/// reported by vtkErrorMacro (the filter's own file and line) and 0, or, for a stop that a
/// progress observer asked for (tessera_vtk::IsStop), nothing reported and 1.
#define tesseraErrorOrStopMacro(e)                                                                 \
  [&]() -> int                                                                                     \
  {                                                                                                \
    if (tessera_vtk::IsStop(e))                                                                    \
    {                                                                                              \
      return 1;                                                                                    \
    }                                                                                              \
    vtkErrorMacro(<< (e).what());                                                                  \
    return 0;                                                                                      \
  }()

/// A warning of self (the filter; its own file and line) saying text, when text is not empty: the
/// warnings' builders here and in the filters return "" for nothing to say.
#define tesseraWarnUnlessEmptyMacro(self, text)                                                    \
  do                                                                                               \
  {                                                                                                \
    const std::string tesseraWarning_ = (text);                                                    \
    if (!tesseraWarning_.empty())                                                                  \
    {                                                                                              \
      vtkWarningWithObjectMacro(self, << tesseraWarning_);                                         \
    }                                                                                              \
  } while (0)

/// A warning of self for each of the texts, in order.
#define tesseraWarnEachMacro(self, texts)                                                          \
  do                                                                                               \
  {                                                                                                \
    for (const std::string& tesseraWarning_ : (texts))                                             \
    {                                                                                              \
      vtkWarningWithObjectMacro(self, << tesseraWarning_);                                         \
    }                                                                                              \
  } while (0)

#endif
