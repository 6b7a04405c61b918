#pragma once
// CAD files for the geometry tests, written here with OpenCASCADE's own API (no binary test data): a box, a cylinder
// with a hole, a two-part assembly with names, a part in millimetres, an IGES of surfaces only, an open solid and a
// truncated STEP. Built only with MPM_WITH_OCCT.
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Writer.hxx>
#include <Interface_Static.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <STEPControl_Controller.hxx>
#include <STEPControl_Writer.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shell.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <gp_Ax2.hxx>
#include <gp_Pln.hxx>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace mpm::test {

/// The box [x0, x0 + a] x [y0, y0 + b] x [z0, z0 + c] (in the unit the writer is told).
inline TopoDS_Shape cad_box(double x0, double y0, double z0, double a, double b, double c) {
  return BRepPrimAPI_MakeBox(gp_Pnt(x0, y0, z0), a, b, c).Shape();
}

/// A tube: the cylinder of radius r_out and height h on the z axis at (cx, cy, z0) less the coaxial one of r_in.
inline TopoDS_Shape cad_tube(double cx, double cy, double z0, double r_out, double r_in, double h) {
  const gp_Ax2 axis(gp_Pnt(cx, cy, z0), gp::DZ());
  const TopoDS_Shape outer = BRepPrimAPI_MakeCylinder(axis, r_out, h).Shape();
  const TopoDS_Shape inner = BRepPrimAPI_MakeCylinder(axis, r_in, h).Shape();
  BRepAlgoAPI_Cut cut(outer, inner);
  if (!cut.IsDone()) throw std::runtime_error("cad_tube: boolean cut failed");
  return cut.Shape();
}

/// Writes `shape` as STEP AP214; its coordinates are in `unit` ("M" or "MM"), which the file records.
inline void write_step(const std::filesystem::path& file, const TopoDS_Shape& shape, const char* unit = "M") {
  STEPControl_Controller::Init();  // first: it sets the defaults of the parameters below
  Interface_Static::SetCVal("xstep.cascade.unit", unit);
  Interface_Static::SetCVal("write.step.unit", unit);
  STEPControl_Writer writer;
  if (writer.Transfer(shape, STEPControl_AsIs) != IFSelect_RetDone ||
      writer.Write(file.string().c_str()) != IFSelect_RetDone)
    throw std::runtime_error("write_step failed: " + file.string());
  Interface_Static::SetCVal("xstep.cascade.unit", "M");
}

/// Writes `shape`, in millimetres, as an IGES file in millimetres (OpenCASCADE 7.6's IGES writer takes the shape in
/// mm whatever it is told): `solids` true writes B-rep solids (MSBO entities, "BRep mode"), false trimmed surfaces.
inline void write_iges(const std::filesystem::path& file, const TopoDS_Shape& shape, bool solids) {
  IGESControl_Controller::Init();
  IGESControl_Writer writer("MM", solids ? 1 : 0);
  writer.AddShape(shape);
  writer.ComputeModel();
  if (!writer.Write(file.string().c_str())) throw std::runtime_error("write_iges failed: " + file.string());
}

inline void write_brep(const std::filesystem::path& file, const TopoDS_Shape& shape) {
  if (!BRepTools::Write(shape, file.string().c_str())) throw std::runtime_error("write_brep failed: " + file.string());
}

/// A named part of an assembly, placed by a translation (m).
struct CadPart {
  std::string name;
  TopoDS_Shape shape;
  gp_Vec translation{0, 0, 0};
};

/// Writes an assembly named `assembly` of the parts (each a product with its name) as STEP AP214, in metres.
inline void write_assembly_step(const std::filesystem::path& file, const std::vector<CadPart>& parts,
                                const std::string& assembly = "assembly") {
  STEPControl_Controller::Init();
  Interface_Static::SetCVal("xstep.cascade.unit", "M");
  Interface_Static::SetCVal("write.step.unit", "M");
  Handle(TDocStd_Document) document;
  XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", document);
  const Handle(XCAFDoc_ShapeTool) tool = XCAFDoc_DocumentTool::ShapeTool(document->Main());
  const TDF_Label root = tool->NewShape();
  TDataStd_Name::Set(root, assembly.c_str());
  for (const auto& part : parts) {
    const TDF_Label label = tool->AddShape(part.shape, false);
    TDataStd_Name::Set(label, part.name.c_str());
    gp_Trsf move;
    move.SetTranslation(part.translation);
    tool->AddComponent(root, label, TopLoc_Location(move));
  }
  tool->UpdateAssemblies();
  STEPCAFControl_Writer writer;
  writer.SetNameMode(true);
  if (!writer.Transfer(document, STEPControl_AsIs) || writer.Write(file.string().c_str()) != IFSelect_RetDone)
    throw std::runtime_error("write_assembly_step failed: " + file.string());
  XCAFApp_Application::GetApplication()->Close(document);
}

/// A unit box without its top face, made a solid: an open shell.
inline TopoDS_Shape cad_open_box() {
  const TopoDS_Shape box = cad_box(0, 0, 0, 1, 1, 1);
  BRep_Builder builder;
  TopoDS_Shell shell;
  builder.MakeShell(shell);
  int k = 0;
  for (TopExp_Explorer e(box, TopAbs_FACE); e.More(); e.Next(), ++k)
    if (k != 5) builder.Add(shell, e.Current());
  TopoDS_Solid solid;
  builder.MakeSolid(solid);
  builder.Add(solid, shell);
  return solid;
}

/// A square face: a surface, not a solid.
inline TopoDS_Shape cad_face() { return BRepBuilderAPI_MakeFace(gp_Pln(gp::XOY()), 0, 1, 0, 1).Shape(); }

}  // namespace mpm::test
