#include "mpm/app/diff_command.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkXMLGenericDataObjectReader.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <ostream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "mpm/app/run_scene.hpp"

namespace mpm::app {
namespace {

namespace fs = std::filesystem;

/// A bad input: reported, exit status 2.
struct BadInput : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The largest differences of one field over the frames (or rows) compared.
struct FieldDifference {
  double absolute = 0, relative = 0;
  int first = -1;  ///< first frame or row that differs, -1 when none
  std::string note;
};

class Comparison {
 public:
  Comparison(double relative, double absolute) : relative_(relative), absolute_(absolute) {}
  /// Values a[i], b[i] of field `name` of `file` in frame (or row) k; `scale` is the largest |a| of the field in
  /// that frame.
  void values(const std::string& file, const std::string& name, int k, double a, double b, double scale) {
    auto& d = fields_[{file, name}];
    const double diff = std::abs(a - b);
    if (!(diff <= std::max(absolute_, relative_ * scale)) && d.first < 0) d.first = k;
    if (std::isnan(diff)) return;
    d.absolute = std::max(d.absolute, diff);
    if (scale > 0) d.relative = std::max(d.relative, diff / scale);
  }
  /// A difference of structure (a missing file, field or frame, other point counts).
  void structure(const std::string& file, const std::string& name, int k, const std::string& note) {
    auto& d = fields_[{file, name}];
    if (d.first < 0) d.first = k;
    if (d.note.empty()) d.note = note;
  }
  int print(std::ostream& out) const {
    int different = 0;
    fmt::print(out, "{:<28} {:<26} {:>12} {:>12}  {}\n", "file", "field", "max |a-b|", "max rel", "first difference");
    for (const auto& [key, d] : fields_) {
      different += d.first >= 0;
      fmt::print(out, "{:<28} {:<26} {:>12.4g} {:>12.4g}  {}\n", key.first, key.second, d.absolute, d.relative,
                 d.first < 0 ? std::string("-") : fmt::format("{} {}", d.first, d.note));
    }
    if (different == 0)
      fmt::print(out, "equal: {} fields within |a-b| <= max({:g}, {:g} |a|max)\n", fields_.size(), absolute_,
                 relative_);
    else
      fmt::print(out, "different: {} of {} fields\n", different, fields_.size());
    return different;
  }

 private:
  double relative_, absolute_;
  std::map<std::pair<std::string, std::string>, FieldDifference> fields_;
};

struct Frame {
  double time;
  std::string file;
};

/// The frames of a .pvd collection (pvd_collection.hpp writes one DataSet element per frame).
std::vector<Frame> read_pvd(const fs::path& pvd) {
  std::ifstream in(pvd);
  if (!in) throw BadInput("cannot read " + pvd.string());
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  static const std::regex dataset(R"re(<DataSet[^>]*timestep="([^"]*)"[^>]*file="([^"]*)")re");
  std::vector<Frame> frames;
  for (auto it = std::sregex_iterator(s.begin(), s.end(), dataset); it != std::sregex_iterator(); ++it)
    frames.push_back({std::stod((*it)[1]), (*it)[2]});
  return frames;
}

vtkSmartPointer<vtkDataSet> read_dataset(const fs::path& file) {
  if (!fs::exists(file)) throw BadInput("missing " + file.string());
  vtkNew<vtkXMLGenericDataObjectReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkSmartPointer<vtkDataSet> data = vtkDataSet::SafeDownCast(reader->GetOutput());
  if (!data) throw BadInput("cannot read " + file.string() + " as VTK XML data");
  return data;
}

/// The B point matching each A point: by (body, id) when both files have unique pairs, else by index.
std::vector<vtkIdType> match_points(vtkDataSet* a, vtkDataSet* b) {
  const vtkIdType n = a->GetNumberOfPoints();
  std::vector<vtkIdType> match(static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i) match[static_cast<std::size_t>(i)] = i;
  auto keys = [](vtkDataSet* d, std::map<std::pair<double, double>, vtkIdType>& out) {
    vtkDataArray* id = d->GetPointData()->GetArray("id");
    vtkDataArray* body = d->GetPointData()->GetArray("body");
    if (!id) return false;
    for (vtkIdType i = 0; i < d->GetNumberOfPoints(); ++i)
      if (!out.emplace(std::make_pair(body ? body->GetComponent(i, 0) : 0.0, id->GetComponent(i, 0)), i).second)
        return false;
    return true;
  };
  std::map<std::pair<double, double>, vtkIdType> ka, kb;
  if (!keys(a, ka) || !keys(b, kb) || ka.size() != kb.size()) return match;
  for (const auto& [key, i] : ka) {
    const auto it = kb.find(key);
    if (it == kb.end()) return match;
    match[static_cast<std::size_t>(i)] = it->second;
  }
  return match;
}

void compare_arrays(Comparison& c, const std::string& file, const std::string& name, int frame, vtkDataArray* a,
                    vtkDataArray* b, const std::vector<vtkIdType>& match) {
  if (a->GetNumberOfComponents() != b->GetNumberOfComponents()) {
    c.structure(file, name, frame, "(other component counts)");
    return;
  }
  const int nc = a->GetNumberOfComponents();
  double scale = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    for (int k = 0; k < nc; ++k) scale = std::max(scale, std::abs(a->GetComponent(i, k)));
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    for (int k = 0; k < nc; ++k)
      c.values(file, name, frame, a->GetComponent(i, k), b->GetComponent(match[static_cast<std::size_t>(i)], k), scale);
}

void compare_series(Comparison& c, const fs::path& a_dir, const fs::path& b_dir, const std::string& pvd) {
  const auto fa = read_pvd(a_dir / pvd);
  if (!fs::exists(b_dir / pvd)) {
    c.structure(pvd, "(series)", 0, "(missing in B)");
    return;
  }
  const auto fb = read_pvd(b_dir / pvd);
  if (fa.size() != fb.size())
    c.structure(pvd, "(frames)", static_cast<int>(std::min(fa.size(), fb.size())),
                fmt::format("({} frames against {})", fa.size(), fb.size()));
  for (std::size_t k = 0; k < std::min(fa.size(), fb.size()); ++k) {
    const int frame = static_cast<int>(k);
    c.values(pvd, "(time)", frame, fa[k].time, fb[k].time, std::abs(fa[k].time));
    auto a = read_dataset(a_dir / fa[k].file);
    auto b = read_dataset(b_dir / fb[k].file);
    if (a->GetNumberOfPoints() != b->GetNumberOfPoints()) {
      c.structure(pvd, "(points)", frame,
                  fmt::format("({} points against {})", a->GetNumberOfPoints(), b->GetNumberOfPoints()));
      continue;
    }
    const auto match = match_points(a, b);
    if (auto* pa = vtkPointSet::SafeDownCast(a))  // particle positions (not on an image grid)
      compare_arrays(c, pvd, "(coordinates)", frame, pa->GetPoints()->GetData(),
                     vtkPointSet::SafeDownCast(b)->GetPoints()->GetData(), match);
    vtkPointData* da = a->GetPointData();
    for (int i = 0; i < da->GetNumberOfArrays(); ++i) {
      vtkDataArray* x = da->GetArray(i);
      if (!x || !x->GetName()) continue;
      vtkDataArray* y = b->GetPointData()->GetArray(x->GetName());
      if (!y)
        c.structure(pvd, x->GetName(), frame, "(missing in B)");
      else
        compare_arrays(c, pvd, x->GetName(), frame, x, y, match);
    }
  }
}

std::vector<std::vector<std::string>> read_csv(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw BadInput("cannot read " + file.string());
  std::vector<std::vector<std::string>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream s(line);
    std::string cell;
    while (std::getline(s, cell, ',')) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.emplace_back();  // a last cell with no data
    rows.push_back(std::move(cells));
  }
  return rows;
}

void compare_csv(Comparison& c, const fs::path& a_dir, const fs::path& b_dir, const std::string& name) {
  if (!fs::exists(b_dir / name)) {
    c.structure(name, "(file)", 0, "(missing in B)");
    return;
  }
  const auto a = read_csv(a_dir / name), b = read_csv(b_dir / name);
  if (a.empty() || b.empty() || a[0] != b[0]) {
    c.structure(name, "(columns)", 0, "(other columns)");
    return;
  }
  if (a.size() != b.size())
    c.structure(name, "(rows)", static_cast<int>(std::min(a.size(), b.size())) - 1,
                fmt::format("({} rows against {})", a.size() - 1, b.size() - 1));
  const auto& header = a[0];
  for (std::size_t col = 0; col < header.size(); ++col) {
    // wall times (solver.csv: wall_seconds and its parts, projection_seconds, ...): not results
    if (header[col].ends_with("_seconds")) continue;
    double scale = 0;
    for (std::size_t r = 1; r < a.size(); ++r)
      if (col < a[r].size()) scale = std::max(scale, std::abs(std::strtod(a[r][col].c_str(), nullptr)));
    for (std::size_t r = 1; r < std::min(a.size(), b.size()); ++r) {
      if (col >= a[r].size() || col >= b[r].size()) continue;
      if (a[r][col].empty() || b[r][col].empty()) {  // no data (an empty probe, a particle that has left)
        if (a[r][col].empty() != b[r][col].empty())
          c.structure(name, header[col], static_cast<int>(r) - 1,
                      a[r][col].empty() ? "(no data in A)" : "(no data in B)");
        continue;
      }
      char* end_a = nullptr;
      char* end_b = nullptr;
      const double x = std::strtod(a[r][col].c_str(), &end_a), y = std::strtod(b[r][col].c_str(), &end_b);
      if (*end_a || *end_b) {  // text (a body's name in the contact forces)
        if (a[r][col] != b[r][col]) c.structure(name, header[col], static_cast<int>(r) - 1, "(other text)");
        continue;
      }
      c.values(name, header[col], static_cast<int>(r) - 1, x, y, scale);
    }
  }
}

std::vector<std::string> files_with(const fs::path& dir, const std::string& extension) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file() && e.path().extension() == extension) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace

int diff_command(const DiffOptions& o, std::ostream& out, std::ostream& err) {
  try {
    for (const auto& dir : {o.a, o.b})
      if (!fs::is_directory(dir)) throw BadInput(dir.string() + " is not a directory");
    if (!(o.relative >= 0) || !(o.absolute >= 0)) throw BadInput("the tolerances must be >= 0");
    const auto series = files_with(o.a, ".pvd");
    const auto tables = files_with(o.a, ".csv");
    if (series.empty() && tables.empty()) throw BadInput(o.a.string() + " holds no .pvd or .csv output");
    Comparison c(o.relative, o.absolute);
    for (const auto& pvd : series) compare_series(c, o.a, o.b, pvd);
    for (const auto& csv : tables) compare_csv(c, o.a, o.b, csv);
    for (const auto& pvd : files_with(o.b, ".pvd"))
      if (!fs::exists(o.a / pvd)) c.structure(pvd, "(series)", 0, "(missing in A)");
    for (const auto& csv : files_with(o.b, ".csv"))
      if (!fs::exists(o.a / csv)) c.structure(csv, "(file)", 0, "(missing in A)");
    return c.print(out) == 0 ? exit_ok : 1;
  } catch (const BadInput& e) {
    err << "error: " << e.what() << '\n';
    return exit_bad_input;
  }
}

}  // namespace mpm::app
