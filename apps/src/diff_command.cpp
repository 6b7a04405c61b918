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
#include <limits>
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
  /// Times of `file` (frames or rows) that one run has and the other has not: a difference of structure, listed
  /// under the table. `first`: the first such frame (or row) of A, or of B when A has none.
  void unmatched(const std::string& file, const std::vector<double>& only_a, const std::vector<double>& only_b,
                 int first) {
    if (only_a.empty() && only_b.empty()) return;
    structure(file, "(times)", first,
              fmt::format("({} times of A and {} of B without a partner: below)", only_a.size(), only_b.size()));
    unmatched_.push_back({file, only_a, only_b});
  }
  int print(std::ostream& out) const {
    int different = 0;
    fmt::print(out, "{:<28} {:<26} {:>12} {:>12}  {}\n", "file", "field", "max |a-b|", "max rel", "first difference");
    for (const auto& [key, d] : fields_) {
      different += d.first >= 0;
      fmt::print(out, "{:<28} {:<26} {:>12.4g} {:>12.4g}  {}\n", key.first, key.second, d.absolute, d.relative,
                 d.first < 0 ? std::string("-") : fmt::format("{} {}", d.first, d.note));
    }
    for (const auto& u : unmatched_) {
      if (!u.only_a.empty()) fmt::print(out, "{}: in A only, t = {}\n", u.file, times_text(u.only_a));
      if (!u.only_b.empty()) fmt::print(out, "{}: in B only, t = {}\n", u.file, times_text(u.only_b));
    }
    if (different == 0)
      fmt::print(out, "equal: {} fields within |a-b| <= max({:g}, {:g} |a|max)\n", fields_.size(), absolute_,
                 relative_);
    else
      fmt::print(out, "different: {} of {} fields\n", different, fields_.size());
    return different;
  }

 private:
  struct Unmatched {
    std::string file;
    std::vector<double> only_a, only_b;
  };
  /// The first eight times, then how many in all.
  static std::string times_text(const std::vector<double>& t) {
    std::string text;
    for (std::size_t i = 0; i < std::min<std::size_t>(t.size(), 8); ++i)
      text += fmt::format("{}{:.9g}", i ? ", " : "", t[i]);
    if (t.size() > 8) text += fmt::format(", ... ({} in all)", t.size());
    return text + " s";
  }
  double relative_, absolute_;
  std::map<std::pair<std::string, std::string>, FieldDifference> fields_;
  std::vector<Unmatched> unmatched_;
};

/// Frames (or rows) of A and B paired by time: two runs with other output intervals write other times, and only
/// the same times are compared (by index, frame 10 of a run every 2.5 us, t = 25 us, met frame 10 of a run every
/// 2.25 us, t = 22.5 us). Times are the same when they differ by at most `tolerance` times the finer of the two
/// runs' spacings (the median gap between consecutive times: the output interval); each time pairs at most once,
/// in order.
struct TimePairs {
  std::vector<std::pair<std::size_t, std::size_t>> pairs;  ///< (index in A, index in B), by increasing time
  std::vector<double> only_a, only_b;                      ///< times without a partner, increasing
  int first_unmatched = -1;                                ///< the first unpaired index of A (else of B), or -1
};

TimePairs pair_by_time(const std::vector<double>& ta, const std::vector<double>& tb, double tolerance) {
  auto order = [](const std::vector<double>& t) {
    std::vector<std::size_t> k(t.size());
    for (std::size_t i = 0; i < k.size(); ++i) k[i] = i;
    std::stable_sort(k.begin(), k.end(), [&](std::size_t i, std::size_t j) { return t[i] < t[j]; });
    return k;
  };
  const auto ka = order(ta), kb = order(tb);
  // A run's spacing is the median gap between its consecutive times (its output interval; the last frame, written
  // where the run ends, may fall just after another).
  double spacing = std::numeric_limits<double>::infinity(), largest = 0;
  auto scan = [&](const std::vector<double>& t, const std::vector<std::size_t>& k) {
    std::vector<double> gaps;
    for (std::size_t i = 0; i < k.size(); ++i) {
      largest = std::max(largest, std::abs(t[k[i]]));
      if (i > 0 && t[k[i]] > t[k[i - 1]]) gaps.push_back(t[k[i]] - t[k[i - 1]]);
    }
    if (gaps.empty()) return;
    std::nth_element(gaps.begin(), gaps.begin() + static_cast<std::ptrdiff_t>(gaps.size() / 2), gaps.end());
    spacing = std::min(spacing, gaps[gaps.size() / 2]);
  };
  scan(ta, ka);
  scan(tb, kb);
  if (!std::isfinite(spacing)) spacing = largest > 0 ? largest : 1;  // one time each
  const double within = tolerance * spacing;
  TimePairs p;
  int first_b = -1;
  std::size_t i = 0, j = 0;
  while (i < ka.size() || j < kb.size()) {
    const double a = i < ka.size() ? ta[ka[i]] : std::numeric_limits<double>::infinity();
    const double b = j < kb.size() ? tb[kb[j]] : std::numeric_limits<double>::infinity();
    if (i < ka.size() && j < kb.size() && std::abs(a - b) <= within) {
      p.pairs.emplace_back(ka[i++], kb[j++]);
    } else if (a < b) {
      p.only_a.push_back(a);
      if (p.first_unmatched < 0) p.first_unmatched = static_cast<int>(ka[i]);
      ++i;
    } else {
      p.only_b.push_back(b);
      if (first_b < 0) first_b = static_cast<int>(kb[j]);
      ++j;
    }
  }
  if (p.first_unmatched < 0) p.first_unmatched = first_b;
  return p;
}

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

void compare_series(Comparison& c, const fs::path& a_dir, const fs::path& b_dir, const std::string& pvd,
                    double time_tolerance) {
  const auto fa = read_pvd(a_dir / pvd);
  if (!fs::exists(b_dir / pvd)) {
    c.structure(pvd, "(series)", 0, "(missing in B)");
    return;
  }
  const auto fb = read_pvd(b_dir / pvd);
  std::vector<double> ta, tb;
  for (const auto& f : fa) ta.push_back(f.time);
  for (const auto& f : fb) tb.push_back(f.time);
  const TimePairs paired = pair_by_time(ta, tb, time_tolerance);
  c.unmatched(pvd, paired.only_a, paired.only_b, paired.first_unmatched);
  for (const auto& [ia, ib] : paired.pairs) {
    const int frame = static_cast<int>(ia);  // A's frame number
    c.values(pvd, "(time)", frame, fa[ia].time, fb[ib].time, std::abs(fa[ia].time));
    auto a = read_dataset(a_dir / fa[ia].file);
    auto b = read_dataset(b_dir / fb[ib].file);
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

void compare_csv(Comparison& c, const fs::path& a_dir, const fs::path& b_dir, const std::string& name,
                 double time_tolerance) {
  if (!fs::exists(b_dir / name)) {
    c.structure(name, "(file)", 0, "(missing in B)");
    return;
  }
  const auto a = read_csv(a_dir / name), b = read_csv(b_dir / name);
  if (a.empty() || b.empty() || a[0] != b[0]) {
    c.structure(name, "(columns)", 0, "(other columns)");
    return;
  }
  const auto& header = a[0];
  // Rows paired by time when the first column is the time (energy.csv, the histories), else by index.
  std::vector<std::pair<std::size_t, std::size_t>> rows;
  if (!header.empty() && (header[0] == "time" || header[0].starts_with("time ["))) {
    std::vector<double> ta, tb;
    for (std::size_t r = 1; r < a.size(); ++r) ta.push_back(a[r].empty() ? 0.0 : std::strtod(a[r][0].c_str(), nullptr));
    for (std::size_t r = 1; r < b.size(); ++r) tb.push_back(b[r].empty() ? 0.0 : std::strtod(b[r][0].c_str(), nullptr));
    const TimePairs paired = pair_by_time(ta, tb, time_tolerance);
    c.unmatched(name, paired.only_a, paired.only_b, paired.first_unmatched);
    for (const auto& [ra, rb] : paired.pairs) rows.emplace_back(ra + 1, rb + 1);
  } else {
    if (a.size() != b.size())
      c.structure(name, "(rows)", static_cast<int>(std::min(a.size(), b.size())) - 1,
                  fmt::format("({} rows against {})", a.size() - 1, b.size() - 1));
    for (std::size_t r = 1; r < std::min(a.size(), b.size()); ++r) rows.emplace_back(r, r);
  }
  for (std::size_t col = 0; col < header.size(); ++col) {
    // wall times (solver.csv: wall_seconds and its parts, projection_seconds, ...): not results
    if (header[col].ends_with("_seconds")) continue;
    double scale = 0;
    for (std::size_t r = 1; r < a.size(); ++r)
      if (col < a[r].size()) scale = std::max(scale, std::abs(std::strtod(a[r][col].c_str(), nullptr)));
    for (const auto& [r, rb] : rows) {
      if (col >= a[r].size() || col >= b[rb].size()) continue;
      if (a[r][col].empty() || b[rb][col].empty()) {  // no data (an empty probe, a particle that has left)
        if (a[r][col].empty() != b[rb][col].empty())
          c.structure(name, header[col], static_cast<int>(r) - 1,
                      a[r][col].empty() ? "(no data in A)" : "(no data in B)");
        continue;
      }
      char* end_a = nullptr;
      char* end_b = nullptr;
      const double x = std::strtod(a[r][col].c_str(), &end_a), y = std::strtod(b[rb][col].c_str(), &end_b);
      if (*end_a || *end_b) {  // text (a body's name in the contact forces)
        if (a[r][col] != b[rb][col]) c.structure(name, header[col], static_cast<int>(r) - 1, "(other text)");
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
    if (!(o.relative >= 0) || !(o.absolute >= 0) || !(o.time_tolerance >= 0))
      throw BadInput("the tolerances must be >= 0");
    const auto series = files_with(o.a, ".pvd");
    const auto tables = files_with(o.a, ".csv");
    if (series.empty() && tables.empty()) throw BadInput(o.a.string() + " holds no .pvd or .csv output");
    Comparison c(o.relative, o.absolute);
    for (const auto& pvd : series) compare_series(c, o.a, o.b, pvd, o.time_tolerance);
    for (const auto& csv : tables) compare_csv(c, o.a, o.b, csv, o.time_tolerance);
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
