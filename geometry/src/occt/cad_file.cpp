// Reading STEP (AP203/AP214/AP242), IGES and BREP files with OpenCASCADE (cad_file.hpp): STEP and IGES through XCAF,
// which keeps the assembly tree and its product and instance names, into a document whose length unit is the metre
// (the readers scale the file's unit to it); BREP with BRepTools. Each solid of each leaf part, in tree order.
#include "cad_file.hpp"

#include <fmt/format.h>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESCAFControl_Reader.hxx>
#include <IGESControl_Controller.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <STEPControl_Controller.hxx>
#include <Standard_Failure.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <UnitsMethods.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>

#include "mpm/geometry/geometry_error.hpp"

namespace mpm::geometry::occt {

namespace {

std::string lower_extension(const std::string& file) {
  std::string ext = std::filesystem::path(file).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

/// OpenCASCADE prints its readers' messages on stdout; the program's output is its own.
void silence_messages() {
  static std::once_flag once;
  std::call_once(once, [] {
    const Handle(Message_Messenger)& messenger = Message::DefaultMessenger();
    messenger->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
  });
}

std::string name_of(const TDF_Label& label) {
  Handle(TDataStd_Name) name;
  if (!label.FindAttribute(TDataStd_Name::GetID(), name)) return "";
  return TCollection_AsciiString(name->Get()).ToCString();
}

/// Appends the solids of `shape` (faces, shells of other kinds are left out here and counted by the caller).
void add_solids(const TopoDS_Shape& shape, const std::string& part, CadModel& model) {
  for (TopExp_Explorer e(shape, TopAbs_SOLID); e.More(); e.Next())
    model.solids.push_back({part, TopoDS::Solid(e.Current())});
}

/// The leaves of the assembly tree under `label`, placed by the locations on the way down. A part is named by its
/// product (the referred label), or by the instance when the product has no name.
void walk(const Handle(XCAFDoc_ShapeTool) & tool, const TDF_Label& label, const TopLoc_Location& parent,
          CadModel& model) {
  TDF_Label product = label;
  TopLoc_Location location = parent;
  if (XCAFDoc_ShapeTool::IsReference(label)) {
    XCAFDoc_ShapeTool::GetReferredShape(label, product);
    location = parent * XCAFDoc_ShapeTool::GetLocation(label);
  }
  if (XCAFDoc_ShapeTool::IsAssembly(product)) {
    TDF_LabelSequence components;
    XCAFDoc_ShapeTool::GetComponents(product, components);
    for (const TDF_Label& component : components) walk(tool, component, location, model);
    return;
  }
  std::string part = name_of(product);
  if (part.empty()) part = name_of(label);
  add_solids(XCAFDoc_ShapeTool::GetShape(product).Moved(location), part, model);
}

CadModel read_with_xcaf(const std::string& file, bool step) {
  Handle(TDocStd_Document) document;
  XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", document);
  // The readers convert the file's unit to the document's, metres (the IGES reader to OpenCASCADE's "cascade" unit,
  // 1000 mm).
  if (step)
    STEPControl_Controller::Init();  // first: it sets the parameters' defaults
  else
    IGESControl_Controller::Init();
  XCAFDoc_DocumentTool::SetLengthUnit(document, 1.0);
  Interface_Static::SetCVal("xstep.cascade.unit", "M");
  UnitsMethods::SetCasCadeLengthUnit(1000.0, UnitsMethods_LengthUnit_Millimeter);
  bool read = false;
  if (step) {
    STEPCAFControl_Reader reader;
    reader.SetNameMode(true);
    read = reader.ReadFile(file.c_str()) == IFSelect_RetDone && reader.Transfer(document);
  } else {
    IGESCAFControl_Reader reader;
    reader.SetNameMode(true);
    read = reader.ReadFile(file.c_str()) == IFSelect_RetDone && reader.Transfer(document);
  }
  const std::string format = step ? "STEP" : "IGES";
  if (!read) throw GeometryError(file, fmt::format("cannot read the {0} file (corrupt, truncated or not {0})", format));
  CadModel model;
  const Handle(XCAFDoc_ShapeTool) tool = XCAFDoc_DocumentTool::ShapeTool(document->Main());
  TDF_LabelSequence roots;
  tool->GetFreeShapes(roots);
  for (const TDF_Label& root : roots) walk(tool, root, TopLoc_Location(), model);
  XCAFApp_Application::GetApplication()->Close(document);
  return model;
}

CadModel read_brep(const std::string& file) {
  TopoDS_Shape shape;
  BRep_Builder builder;
  if (!BRepTools::Read(shape, file.c_str(), builder) || shape.IsNull())
    throw GeometryError(file, "cannot read the BREP file (corrupt, truncated or not an OpenCASCADE BREP)");
  CadModel model;
  add_solids(shape, "", model);
  return model;
}

/// What the file holds instead of solids, for the message.
std::string no_solid_message(const std::string& file) {
  const std::string ext = lower_extension(file);
  return fmt::format("the file has no solid (a surface model{}): export the parts as solids{}",
                     ext == ".iges" || ext == ".igs" ? ", e.g. IGES trimmed surfaces without MSBO solid entities" : "",
                     ext == ".iges" || ext == ".igs" ? " (IGES 'BRep' / MSBO mode) or as STEP" : "");
}

CadModel read_model(const std::string& file) {
  silence_messages();
  const std::string ext = lower_extension(file);
  std::error_code error;
  if (!std::filesystem::exists(file, error)) throw GeometryError(file, "CAD file not found");
  if (std::filesystem::file_size(file, error) == 0) throw GeometryError(file, "the CAD file is empty");
  CadModel model;
  try {
    if (ext == ".step" || ext == ".stp")
      model = read_with_xcaf(file, true);
    else if (ext == ".iges" || ext == ".igs")
      model = read_with_xcaf(file, false);
    else if (ext == ".brep" || ext == ".brp")
      model = read_brep(file);
    else
      throw GeometryError(file,
                          fmt::format("unsupported CAD format '{}' (supported: .step, .stp, .iges, .igs, .brep)", ext));
  } catch (const Standard_Failure& failure) {
    throw GeometryError(file, fmt::format("OpenCASCADE failed to read the file: {}", failure.GetMessageString()));
  }
  if (model.solids.empty()) throw GeometryError(file, no_solid_message(file));
  return model;
}

}  // namespace

const CadModel& cad_model(const std::string& file) {
  static std::mutex mutex;
  static std::map<std::string, std::unique_ptr<const CadModel>> models;
  const std::scoped_lock lock(mutex);
  auto& model = models[file];
  if (!model) model = std::make_unique<const CadModel>(read_model(file));
  return *model;
}

std::vector<detail::CadSolidInfo> cad_solids(const std::string& file) {
  const CadModel& model = cad_model(file);
  std::vector<detail::CadSolidInfo> solids;
  solids.reserve(model.solids.size());
  for (std::size_t k = 0; k < model.solids.size(); ++k) solids.push_back({model.solids[k].part, k});
  return solids;
}

}  // namespace mpm::geometry::occt
