// The Gmsh .msh reader (mpm/geometry/gmsh_mesh.hpp): sections $MeshFormat, $PhysicalNames, $Entities (4.1),
// $Nodes and $Elements; any other section is skipped. Format references: the Gmsh manual, "MSH file format"
// (version 4.1) and "Legacy formats" (version 2.2).
#include <fmt/format.h>

#include <charconv>
#include <fstream>
#include <sstream>
#include <string_view>
#include <unordered_map>

#include "mpm/geometry/geometry_error.hpp"
#include "mpm/geometry/gmsh_mesh.hpp"

namespace mpm::geometry {

std::pair<int, int> gmsh_element_shape(int type) {
  // {nodes, dimension} of Gmsh's element types 1 to 19 (first and second order) and 15 (point).
  static const std::unordered_map<int, std::pair<int, int>> shapes{
      {1, {2, 1}},  {2, {3, 2}},  {3, {4, 2}},   {4, {4, 3}},   {5, {8, 3}},   {6, {6, 3}},   {7, {5, 3}},
      {8, {3, 1}},  {9, {6, 2}},  {10, {9, 2}},  {11, {10, 3}}, {12, {27, 3}}, {13, {18, 3}}, {14, {14, 3}},
      {15, {1, 0}}, {16, {8, 2}}, {17, {20, 3}}, {18, {15, 3}}, {19, {13, 3}}};
  const auto it = shapes.find(type);
  return it == shapes.end() ? std::pair<int, int>{0, -1} : it->second;
}

namespace {

/// Whitespace-separated tokens with their line numbers.
class Tokens {
 public:
  Tokens(std::string file, std::string text) : file_(std::move(file)), text_(std::move(text)) {}

  /// The next token ("" at the end of the file).
  std::string_view next() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) {
      if (text_[pos_] == '\n') ++line_;
      ++pos_;
    }
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    return std::string_view(text_).substr(start, pos_ - start);
  }
  /// The rest of the current line (a quoted name), trimmed.
  std::string rest_of_line() {
    const std::size_t end = text_.find('\n', pos_);
    std::string rest = text_.substr(pos_, end == std::string::npos ? std::string::npos : end - pos_);
    pos_ = end == std::string::npos ? text_.size() : end;
    const auto first = rest.find_first_not_of(" \t\r"), last = rest.find_last_not_of(" \t\r");
    return first == std::string::npos ? "" : rest.substr(first, last - first + 1);
  }
  template <class T>
  T number(std::string_view what) {
    const std::string_view token = next();
    if (token.empty()) fail(fmt::format("the file ends where {} was expected (truncated?)", what));
    T value{};
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size())
      fail(fmt::format("expected {}, got '{}'", what, token));
    return value;
  }
  void expect(std::string_view keyword) {
    const std::string_view token = next();
    if (token != keyword)
      fail(token.empty() ? fmt::format("the file ends before {} (truncated?)", keyword)
                         : fmt::format("expected {}, got '{}'", keyword, token));
  }
  /// Skips to the token `keyword`.
  void skip_to(std::string_view keyword) {
    for (std::string_view token = next(); token != keyword; token = next())
      if (token.empty()) fail(fmt::format("the file ends before {} (truncated?)", keyword));
  }
  std::size_t line() const { return line_; }
  [[noreturn]] void fail(const std::string& problem) const {
    throw GeometryError(file_, fmt::format("line {}: {}", line_, problem));
  }

 private:
  std::string file_, text_;
  std::size_t pos_ = 0, line_ = 1;
};

/// Node tags to indices.
using NodeIndex = std::unordered_map<long, std::size_t>;

void read_physical_names(Tokens& in, GmshMesh& mesh) {
  const int count = in.number<int>("the number of physical names");
  for (int k = 0; k < count; ++k) {
    const int dimension = in.number<int>("a physical group's dimension");
    const int tag = in.number<int>("a physical group's tag");
    std::string name = in.rest_of_line();
    if (name.size() >= 2 && name.front() == '"' && name.back() == '"') name = name.substr(1, name.size() - 2);
    mesh.physical_names[{dimension, tag}] = name;
  }
  in.expect("$EndPhysicalNames");
}

/// 4.1: the physical tags of every entity, by (dimension, entity tag).
using EntityPhysicals = std::map<std::pair<int, int>, std::vector<int>>;

EntityPhysicals read_entities(Tokens& in) {
  EntityPhysicals physicals;
  std::array<long, 4> counts{};
  for (auto& c : counts) c = in.number<long>("the number of entities");
  for (int dimension = 0; dimension < 4; ++dimension)
    for (long k = 0; k < counts[static_cast<std::size_t>(dimension)]; ++k) {
      const int tag = in.number<int>("an entity tag");
      for (int c = 0; c < (dimension == 0 ? 3 : 6); ++c) in.number<double>("a coordinate of the entity's box");
      const long n = in.number<long>("the number of physical tags");
      auto& tags = physicals[{dimension, tag}];
      for (long p = 0; p < n; ++p) tags.push_back(in.number<int>("a physical tag"));
      if (dimension > 0) {
        const long bounding = in.number<long>("the number of bounding entities");
        for (long b = 0; b < bounding; ++b) in.number<int>("a bounding entity tag");
      }
    }
  in.expect("$EndEntities");
  return physicals;
}

void read_nodes_2(Tokens& in, GmshMesh& mesh, NodeIndex& index) {
  const long count = in.number<long>("the number of nodes");
  mesh.nodes.reserve(static_cast<std::size_t>(count));
  for (long k = 0; k < count; ++k) {
    const long tag = in.number<long>("a node tag");
    std::array<double, 3> x{};
    for (auto& c : x) c = in.number<double>("a node coordinate");
    index[tag] = mesh.nodes.size();
    mesh.nodes.push_back(x);
  }
  in.expect("$EndNodes");
}

void read_nodes_4(Tokens& in, GmshMesh& mesh, NodeIndex& index) {
  const long blocks = in.number<long>("the number of node blocks");
  mesh.nodes.reserve(static_cast<std::size_t>(in.number<long>("the number of nodes")));
  in.number<long>("the smallest node tag");
  in.number<long>("the largest node tag");
  for (long b = 0; b < blocks; ++b) {
    in.number<int>("the block's entity dimension");
    in.number<int>("the block's entity tag");
    const int parametric = in.number<int>("the block's parametric flag");
    const long count = in.number<long>("the number of nodes in the block");
    std::vector<long> tags;
    tags.reserve(static_cast<std::size_t>(count));
    for (long k = 0; k < count; ++k) tags.push_back(in.number<long>("a node tag"));
    for (long k = 0; k < count; ++k) {
      std::array<double, 3> x{};
      for (auto& c : x) c = in.number<double>("a node coordinate");
      for (int p = 0; p < parametric; ++p) in.number<double>("a parametric coordinate");
      index[tags[static_cast<std::size_t>(k)]] = mesh.nodes.size();
      mesh.nodes.push_back(x);
    }
  }
  in.expect("$EndNodes");
}

/// An element's node tags made indices.
std::vector<std::size_t> element_nodes(Tokens& in, const NodeIndex& index, int type, long tag) {
  const auto [count, dimension] = gmsh_element_shape(type);
  if (dimension < 0) in.fail(fmt::format("element {} has the unknown element type {}", tag, type));
  std::vector<std::size_t> nodes;
  nodes.reserve(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) {
    const long node = in.number<long>("a node tag of an element");
    const auto it = index.find(node);
    if (it == index.end())
      in.fail(fmt::format("element {} refers to node {}, which $Nodes does not define", tag, node));
    nodes.push_back(it->second);
  }
  return nodes;
}

void read_elements_2(Tokens& in, GmshMesh& mesh, const NodeIndex& index) {
  const long count = in.number<long>("the number of elements");
  mesh.elements.reserve(static_cast<std::size_t>(count));
  for (long k = 0; k < count; ++k) {
    GmshElement e;
    e.tag = in.number<long>("an element tag");
    e.line = in.line();
    e.type = in.number<int>("an element type");
    const int tags = in.number<int>("the number of element tags");
    for (int t = 0; t < tags; ++t) {
      const int value = in.number<int>("an element tag");
      if (t == 0 && value != 0) e.physicals.push_back(value);  // the physical group; then the elementary entity
    }
    e.nodes = element_nodes(in, index, e.type, e.tag);
    e.dimension = gmsh_element_shape(e.type).second;
    mesh.elements.push_back(std::move(e));
  }
  in.expect("$EndElements");
}

void read_elements_4(Tokens& in, GmshMesh& mesh, const NodeIndex& index, const EntityPhysicals& physicals) {
  const long blocks = in.number<long>("the number of element blocks");
  mesh.elements.reserve(static_cast<std::size_t>(in.number<long>("the number of elements")));
  in.number<long>("the smallest element tag");
  in.number<long>("the largest element tag");
  for (long b = 0; b < blocks; ++b) {
    const int dimension = in.number<int>("the block's entity dimension");
    const int entity = in.number<int>("the block's entity tag");
    const int type = in.number<int>("the block's element type");
    const long count = in.number<long>("the number of elements in the block");
    const auto found = physicals.find({dimension, entity});
    for (long k = 0; k < count; ++k) {
      GmshElement e;
      e.tag = in.number<long>("an element tag");
      e.line = in.line();
      e.type = type;
      e.nodes = element_nodes(in, index, type, e.tag);
      e.dimension = gmsh_element_shape(type).second;
      if (found != physicals.end()) e.physicals = found->second;
      mesh.elements.push_back(std::move(e));
    }
  }
  in.expect("$EndElements");
}

}  // namespace

GmshMesh read_gmsh(const std::string& file) {
  std::ifstream stream(file, std::ios::binary);
  if (!stream) throw GeometryError(file, "cannot open the Gmsh file");
  std::stringstream buffer;
  buffer << stream.rdbuf();
  Tokens in(file, buffer.str());
  GmshMesh mesh;
  mesh.file = file;
  in.expect("$MeshFormat");
  const std::string version(in.next());
  const int binary = in.number<int>("the file type (0 ASCII, 1 binary)");
  in.number<int>("the size of a double");
  if (version != "2.2" && version != "4.1")
    in.fail(
        fmt::format("Gmsh format {} is not read (2.2 and 4.1 are; Gmsh: File > Export, or -format msh41)", version));
  if (binary != 0) in.fail("binary .msh files are not read; save it as ASCII (Gmsh: Mesh.Binary = 0, or -bin 0)");
  in.skip_to("$EndMeshFormat");
  NodeIndex index;
  EntityPhysicals physicals;
  bool nodes = false, elements = false;
  for (std::string_view section = in.next(); !section.empty(); section = in.next()) {
    if (section == "$PhysicalNames") {
      read_physical_names(in, mesh);
    } else if (section == "$Entities" && version == "4.1") {
      physicals = read_entities(in);
    } else if (section == "$Nodes") {
      version == "2.2" ? read_nodes_2(in, mesh, index) : read_nodes_4(in, mesh, index);
      nodes = true;
    } else if (section == "$Elements") {
      if (!nodes) in.fail("$Elements comes before $Nodes");
      version == "2.2" ? read_elements_2(in, mesh, index) : read_elements_4(in, mesh, index, physicals);
      elements = true;
    } else if (section.size() > 1 && section.front() == '$') {  // another section: skipped
      in.skip_to("$End" + std::string(section.substr(1)));
    } else {
      in.fail(fmt::format("expected a section ($Nodes, $Elements, ...), got '{}'", section));
    }
  }
  if (!elements) throw GeometryError(file, "the Gmsh file has no $Elements section");
  mesh.version = version;
  return mesh;
}

}  // namespace mpm::geometry
