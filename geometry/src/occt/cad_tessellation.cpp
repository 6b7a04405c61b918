// One solid of a CAD file checked, placed and tessellated (cad_model.hpp): BRepCheck_Analyzer for a valid B-rep,
// ShapeAnalysis_Shell for an open shell, BRepGProp for the exact volume, centroid and inertia, BRepMesh for the
// triangles (chordal deviation `tolerance`, angular deviation `angular_tolerance`).
#include <fmt/format.h>
#include <BRepBndLib.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <Poly_Triangulation.hxx>
#include <ShapeAnalysis_Shell.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Face.hxx>

#include <cmath>
#include <mutex>
#include <numbers>

#include "cad_file.hpp"
#include "mpm/geometry/geometry_error.hpp"

namespace mpm::geometry::occt {

using detail::CadTessellation;

namespace {

/// x -> R (scale x) + t (scale: the shape's times the model's unit), R = Rz Ry Rx (degrees), as mesh files are placed
/// (surface_mesh_io.cpp).
gp_Trsf placement(const CadShape& shape, double scale) {
  const double to_rad = std::numbers::pi / 180;
  gp_Trsf scale_by, rx, ry, rz, move;
  scale_by.SetScale(gp_Pnt(0, 0, 0), scale);
  rx.SetRotation(gp::OX(), shape.rotation[0] * to_rad);
  ry.SetRotation(gp::OY(), shape.rotation[1] * to_rad);
  rz.SetRotation(gp::OZ(), shape.rotation[2] * to_rad);
  move.SetTranslation(gp_Vec(shape.translation[0], shape.translation[1], shape.translation[2]));
  return move * rz * ry * rx * scale_by;
}

std::size_t count(const TopoDS_Shape& shape, TopAbs_ShapeEnum kind) {
  std::size_t n = 0;
  for (TopExp_Explorer e(shape, kind); e.More(); e.Next()) ++n;
  return n;
}

/// Refuses a solid that is not a valid closed B-rep.
void check_solid(const TopoDS_Shape& solid, const std::string& file, const std::string& name) {
  ShapeAnalysis_Shell shells;
  shells.LoadShells(solid);
  shells.CheckOrientedShells(solid, true);  // also finds the free edges
  if (shells.HasFreeEdges()) {
    const std::size_t edges = count(shells.FreeEdges(), TopAbs_EDGE);
    throw GeometryError(file, fmt::format("{} is open: {} edge{} bound{} a single face (the solid's shell has a hole; "
                                          "repair it in the CAD program)",
                                          name, edges, edges == 1 ? "" : "s", edges == 1 ? "s" : ""));
  }
  if (!BRepCheck_Analyzer(solid).IsValid())
    throw GeometryError(file, fmt::format("{} is not a valid B-rep (OpenCASCADE's BRepCheck_Analyzer refuses it: "
                                          "faces, edges or tolerances are inconsistent)",
                                          name));
}

MassProperties properties_of(const TopoDS_Shape& solid) {
  GProp_GProps props;
  BRepGProp::VolumeProperties(solid, props);
  MassProperties p;
  p.volume = props.Mass();
  const gp_Pnt c = props.CentreOfMass();
  p.centroid = Vec<3>(c.X(), c.Y(), c.Z());
  const gp_Mat m = props.MatrixOfInertia();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) p.inertia(i, j) = m.Value(i + 1, j + 1);
  return p;
}

/// The properties of a solid placed by x -> R (s x) + t: volume s^3 V, centroid R (s c) + t, inertia s^5 R I R^T.
MassProperties place(const MassProperties& p, const gp_Trsf& placed, double scale) {
  MassProperties q;
  q.volume = p.volume * scale * scale * scale;
  const gp_Pnt c = gp_Pnt(p.centroid[0], p.centroid[1], p.centroid[2]).Transformed(placed);
  q.centroid = Vec<3>(c.X(), c.Y(), c.Z());
  Mat<3> R;
  const gp_Mat rotation = placed.VectorialPart();  // s R
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) R(i, j) = rotation.Value(i + 1, j + 1) / scale;
  q.inertia = std::pow(scale, 5) * R * p.inertia * R.transpose();
  return q;
}

void add_triangles(const TopoDS_Shape& solid, const std::string& file, const std::string& name, const gp_Trsf& placed,
                   CadTessellation& out) {
  std::size_t face_index = 0;
  for (TopExp_Explorer e(solid, TopAbs_FACE); e.More(); e.Next(), ++face_index) {
    const TopoDS_Face& face = TopoDS::Face(e.Current());
    TopLoc_Location location;
    const Handle(Poly_Triangulation) triangulation = BRep_Tool::Triangulation(face, location);
    if (triangulation.IsNull())
      throw GeometryError(file, fmt::format("{}: face {} could not be tessellated", name, face_index));
    const gp_Trsf to_place = placed * location.Transformation();
    const std::size_t offset = out.points.size();
    out.points.reserve(offset + static_cast<std::size_t>(triangulation->NbNodes()));
    for (int k = 1; k <= triangulation->NbNodes(); ++k) {
      const gp_Pnt p = triangulation->Node(k).Transformed(to_place);
      out.points.push_back({p.X(), p.Y(), p.Z()});
    }
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    out.triangles.reserve(out.triangles.size() + static_cast<std::size_t>(triangulation->NbTriangles()));
    for (int k = 1; k <= triangulation->NbTriangles(); ++k) {
      int a = 0, b = 0, c = 0;
      triangulation->Triangle(k).Get(a, b, c);
      if (reversed) std::swap(b, c);
      out.triangles.push_back({offset + static_cast<std::size_t>(a - 1), offset + static_cast<std::size_t>(b - 1),
                               offset + static_cast<std::size_t>(c - 1)});
    }
  }
}

}  // namespace

CadTessellation tessellate_cad_solid(const CadShape& shape, std::size_t index) {
  const CadModel& model = cad_model(shape.file);
  const auto& entry = model.solids.at(index);
  const std::string name =
      entry.part.empty() ? fmt::format("solid #{}", index) : fmt::format("solid '{}' (#{})", entry.part, index);
  CadTessellation out;
  out.label = fmt::format("{}: {}", shape.file, name);
  // The triangulation is stored on the cached model's faces (shared by the instances of a part): one at a time.
  static std::mutex mutex;
  const std::scoped_lock lock(mutex);
  try {
    // Checked, measured and meshed where the file puts it (a copy placed by BRepBuilderAPI_Transform lost the
    // triangulation of IGES faces); the triangles and properties are placed after.
    const TopoDS_Shape& solid = entry.solid;
    check_solid(solid, shape.file, name);
    const double scale = shape.scale * model.unit;
    const gp_Trsf to_place = placement(shape, scale);
    out.exact = place(properties_of(solid), to_place, scale);
    if (!(out.exact.volume > 0))
      throw GeometryError(shape.file, fmt::format("{} encloses no volume (B-rep volume {:.6g} m^3: empty or inside "
                                                  "out)",
                                                  name, out.exact.volume));
    Bnd_Box box;
    BRepBndLib::Add(solid, box);
    const double size = std::sqrt(box.SquareExtent()) * scale;
    out.tolerance = shape.tolerance.value_or(1e-4 * size);
    BRepTools::Clean(solid);  // a coarser or finer triangulation of an earlier body is not reused
    const BRepMesh_IncrementalMesh mesher(solid, out.tolerance / scale, false,
                                          shape.angular_tolerance * std::numbers::pi / 180, false);
    if (!mesher.IsDone()) throw GeometryError(shape.file, fmt::format("{} could not be tessellated", name));
    add_triangles(solid, shape.file, name, to_place, out);
  } catch (const Standard_Failure& failure) {
    throw GeometryError(shape.file, fmt::format("{}: OpenCASCADE failed: {}", name, failure.GetMessageString()));
  }
  return out;
}

}  // namespace mpm::geometry::occt
