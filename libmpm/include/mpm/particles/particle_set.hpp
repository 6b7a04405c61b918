#pragma once
/// \file particle_set.hpp
/// Particle storage by field. The velocity gradient is not state: it lives for one step in a per-block
/// scratch buffer of the scheme (stored in the on-demand field "velocity_gradient" only when asked).
/// The core fields that every scheme reads are typed members; fields that
/// only some scenes need (reference position for displacement, temperature, plastic strain, ...) are
/// added on demand by key (field_keys.hpp; or by name) with add_field() and resolved to a std::vector once
/// per step, never looked up per particle. Every field follows reordering (sort by cell) and snapshots.
/// generation() tells code that holds the address of a field's values (the Python package's NumPy views)
/// when that address or the order of the particles may have changed.
/// Every field, core or on-demand, can be packed to bytes and unpacked by name (field_layout(),
/// pack_field/unpack_field, pack/append_packed): checkpoints and the migration of particles between ranks
/// use that one mechanism, so a new field is checkpointed and migrated without code of its own.

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <functional>
#include <iterator>
#include <map>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "mpm/core/parallel_chunks.hpp"
#include "mpm/grid/grid.hpp"
#include "mpm/particles/field_key.hpp"
#include "mpm/particles/field_layout.hpp"
#include "mpm/particles/field_storage.hpp"

namespace mpm {

namespace detail {
/// Reorders v; the previous buffer is kept as per-thread scratch for the next reordering, so that
/// periodic sorting does not allocate (and page-fault) a fresh array every time. The scratch never gives its storage
/// to a smaller array: swapped into a smaller body's field (or an empty one: a body held by another rank), it left
/// the scratch too small for the larger body's next sort, which then faulted in fresh pages (PERFORMANCE.md §16.6);
/// such an array takes a copy instead.
template <class T>
void gather_vector(std::vector<T>& v, const std::vector<Index>& order) {
  thread_local std::vector<T> scratch;
  auto& out = scratch;  // the calling thread's: a lambda naming `scratch` would reach each worker's own
  out.resize(order.size());
  // Threads take blocks of the new order (each value is written once, so the result is the same for any count).
  parallel_chunks(std::size_t{0}, order.size(), std::size_t{1} << 14,
                  [&](std::size_t chunk_begin, std::size_t chunk_end) {
                    for (std::size_t i = chunk_begin; i != chunk_end; ++i) out[i] = v[order[i]];
                  });
  if (out.capacity() <= v.capacity())
    v.swap(out);
  else {
    v.resize(out.size());  // a gather may leave particles out (migration): never longer
    std::copy(out.begin(), out.end(), v.begin());
  }
}
/// The values of `which` (in that order) as bytes at `out`, sizeof(T) each. Fields are plain values
/// (numbers, fixed-size Eigen matrices, structs of them): copied byte for byte.
template <class T>
std::byte* pack_values(const std::vector<T>& v, std::span<const Index> which, std::byte* out) {
  for (const Index i : which) {
    std::memcpy(out, static_cast<const void*>(&v[i]), sizeof(T));
    out += sizeof(T);
  }
  return out;
}
/// Copies `count` values from `in` into v[first ..] (v must hold them).
template <class T>
const std::byte* unpack_values(std::vector<T>& v, std::size_t first, std::size_t count, const std::byte* in) {
  if (count > 0) std::memcpy(static_cast<void*>(v.data() + first), in, count * sizeof(T));
  return in + count * sizeof(T);
}
/// Type-erased on-demand field, so that reordering and snapshots reach every field.
struct FieldBase {
  virtual ~FieldBase() = default;
  virtual void gather(const std::vector<Index>& order) = 0;  ///< new[i] = old[order[i]]
  virtual void resize(std::size_t n) = 0;
  virtual std::unique_ptr<FieldBase> clone() const = 0;
  /// Copies `o` (a field of the same type) into this one, reusing the storage: no allocation when the
  /// sizes agree (snapshots are taken every few steps into the same buffers).
  virtual bool assign(const FieldBase& o) = 0;
  virtual std::size_t bytes_per_particle() const = 0;
  virtual FieldStorage storage() = 0;
  virtual FieldLayout layout(std::string_view name) const = 0;
  virtual std::byte* pack(std::span<const Index> which, std::byte* out) const = 0;
  virtual const std::byte* unpack(std::size_t first, std::size_t count, const std::byte* in) = 0;
};
template <class T>
struct TypedField final : FieldBase {
  std::vector<T> data;
  T initial{};
  void gather(const std::vector<Index>& order) override { gather_vector(data, order); }
  void resize(std::size_t n) override { data.resize(n, initial); }
  std::unique_ptr<FieldBase> clone() const override { return std::make_unique<TypedField>(*this); }
  bool assign(const FieldBase& o) override {
    const auto* t = dynamic_cast<const TypedField*>(&o);
    if (!t) return false;
    data = t->data;
    initial = t->initial;
    return true;
  }
  std::size_t bytes_per_particle() const override { return sizeof(T); }
  FieldStorage storage() override { return field_storage(data); }
  FieldLayout layout(std::string_view name) const override { return field_layout_of<T>(name); }
  std::byte* pack(std::span<const Index> which, std::byte* out) const override { return pack_values(data, which, out); }
  const std::byte* unpack(std::size_t first, std::size_t count, const std::byte* in) override {
    return unpack_values(data, first, count, in);
  }
};
/// A value that is new, different from every value any particle set had before, whenever the set is created,
/// copied, moved (both sides) or bump()ed: a set's generation() changes with the addresses of its values.
class StorageGeneration {
 public:
  StorageGeneration() = default;
  StorageGeneration(const StorageGeneration& /*other*/) {}
  StorageGeneration(StorageGeneration&& other) noexcept { other.bump(); }
  StorageGeneration& operator=(const StorageGeneration& other) {
    if (this != &other) bump();
    return *this;
  }
  StorageGeneration& operator=(StorageGeneration&& other) noexcept {
    bump();
    other.bump();
    return *this;
  }
  ~StorageGeneration() = default;
  std::uint64_t value() const { return value_; }
  void bump() { value_ = next(); }

 private:
  static std::uint64_t next() {
    static std::atomic<std::uint64_t> counter{0};
    return counter.fetch_add(1, std::memory_order_relaxed) + 1;
  }
  std::uint64_t value_ = next();
};
}  // namespace detail

/// The particles of one body (one material).
template <int Dim>
class ParticleSet {
 public:
  // Core fields (SI units). Volume is not stored: V = volume0 * det(F) (eq. 2.55c).
  std::vector<VecU<Dim>> x;            ///< position, m
  std::vector<VecU<Dim>> v;            ///< velocity, m/s
  std::vector<Real> mass;              ///< kg (kg/m in 2D, kg/m^2 in 1D: per unit out-of-plane size)
  std::vector<Real> volume0;           ///< reference volume, m^3 (per unit out-of-plane size)
  std::vector<MatU<Dim>> F;            ///< deformation gradient
  std::vector<SymTensor<Dim>> stress;  ///< Cauchy stress, Pa
  std::vector<std::uint32_t> id;       ///< index at creation: stable under reordering

  ParticleSet() = default;
  ParticleSet(const ParticleSet& o) { *this = o; }
  ParticleSet& operator=(const ParticleSet& o) {
    if (this == &o) return *this;
    generation_.bump();
    x = o.x;
    v = o.v;
    mass = o.mass;
    volume0 = o.volume0;
    F = o.F;
    stress = o.stress;
    id = o.id;
    // Fields present on both sides are copied in place; the rest are cloned or dropped.
    for (auto it = extra_.begin(); it != extra_.end();)
      it = o.extra_.count(it->first) ? std::next(it) : extra_.erase(it);
    for (const auto& [name, f] : o.extra_) {
      auto it = extra_.find(name);
      if (it == extra_.end() || !it->second->assign(*f)) extra_[name] = f->clone();
    }
    return *this;
  }
  ParticleSet(ParticleSet&&) noexcept = default;
  ParticleSet& operator=(ParticleSet&&) noexcept = default;

  Index size() const { return static_cast<Index>(x.size()); }

  /// Appends one particle at rest with F = I and zero stress.
  void add(const Vec<Dim>& position, Real particle_mass, Real particle_volume) {
    x.push_back(position);
    v.push_back(VecU<Dim>::Zero());
    mass.push_back(particle_mass);
    volume0.push_back(particle_volume);
    F.push_back(MatU<Dim>::Identity());
    stress.push_back(SymTensor<Dim>{});
    id.push_back(static_cast<std::uint32_t>(id.size()));
    for (auto& [name, f] : extra_) f->resize(x.size());
    generation_.bump();
  }

  /// Adds (or returns) an on-demand field with an initial value (give one explicitly for Eigen types,
  /// whose T{} is uninitialised). Call before the time loop.
  template <class T>
  std::vector<T>& add_field(std::string_view name, const T& initial = T{}) {
    auto it = extra_.find(name);
    if (it == extra_.end()) {
      auto f = std::make_unique<detail::TypedField<T>>();
      f->initial = initial;
      f->data.assign(x.size(), initial);
      it = extra_.emplace(std::string(name), std::move(f)).first;
    }
    return typed<T>(it->second.get(), name).data;
  }
  /// add_field by key: the type comes from the key.
  template <class T>
  std::vector<T>& add_field(FieldKey<T> key, const std::type_identity_t<T>& initial = T{}) {
    return add_field<T>(key.name, initial);
  }
  bool has_field(std::string_view name) const { return extra_.find(name) != extra_.end(); }
  template <class T>
  bool has_field(FieldKey<T> key) const {
    return has_field(key.name);
  }
  /// An on-demand field; throws std::out_of_range naming the field if it was never added.
  template <class T>
  std::vector<T>& field(std::string_view name) {
    auto it = extra_.find(name);
    if (it == extra_.end()) throw std::out_of_range("particle field '" + std::string(name) + "' was not allocated");
    return typed<T>(it->second.get(), name).data;
  }
  template <class T>
  const std::vector<T>& field(std::string_view name) const {
    return const_cast<ParticleSet*>(this)->field<T>(name);
  }
  /// field by key: the type comes from the key.
  template <class T>
  std::vector<T>& field(FieldKey<T> key) {
    return field<T>(key.name);
  }
  template <class T>
  const std::vector<T>& field(FieldKey<T> key) const {
    return field<T>(key.name);
  }

  /// Reorders every field: new particle i is old particle order[i].
  void gather(const std::vector<Index>& order) {
    detail::gather_vector(x, order);
    detail::gather_vector(v, order);
    detail::gather_vector(mass, order);
    detail::gather_vector(volume0, order);
    detail::gather_vector(F, order);
    detail::gather_vector(stress, order);
    detail::gather_vector(id, order);
    for (auto& [name, f] : extra_) f->gather(order);
    generation_.bump();
  }

  /// Changes whenever the particles may have moved in memory or been reordered: gather() (the sort by cell
  /// every `solver.sort_interval` steps; TLMPM sorts once, at the start), add() and resize() (the vectors may
  /// grow or shrink; append_packed() and a restart resize), and
  /// assignment (the stability guard's roll-back restores a snapshot) or a move. The values of a field and
  /// its address are unchanged between two calls that return the same number; adding an on-demand field
  /// moves none of the others.
  std::uint64_t generation() const { return generation_.value(); }
  /// Names of the on-demand fields, in name order.
  std::vector<std::string> field_names() const {
    std::vector<std::string> names;
    for (const auto& [name, f] : extra_) names.push_back(name);
    return names;
  }
  /// Where the values of an on-demand field lie (field_storage.hpp); throws std::out_of_range as field().
  FieldStorage storage(std::string_view name) {
    auto it = extra_.find(name);
    if (it == extra_.end()) throw std::out_of_range("particle field '" + std::string(name) + "' was not allocated");
    return it->second->storage();
  }

  /// State bytes per particle: the core fields plus the on-demand fields this scene allocated.
  std::size_t bytes_per_particle() const {
    std::size_t b =
        2 * sizeof(VecU<Dim>) + 2 * sizeof(Real) + sizeof(MatU<Dim>) + sizeof(SymTensor<Dim>) + sizeof(std::uint32_t);
    for (const auto& [name, f] : extra_) b += f->bytes_per_particle();
    return b;
  }

  // ---- Every field as bytes (field_layout.hpp): checkpoints and particle migration ----

  /// Every field: the core ones (position, velocity, mass, reference_volume, deformation_gradient, stress,
  /// id), then the on-demand ones by name. pack() and append_packed() use this order.
  std::vector<FieldLayout> field_layout() const {
    std::vector<FieldLayout> layout;
    for_each_core_field([&](std::string_view name, const auto& v) {
      layout.push_back(field_layout_of<typename std::decay_t<decltype(v)>::value_type>(name));
    });
    for (const auto& [name, f] : extra_) layout.push_back(f->layout(name));
    return layout;
  }
  /// Appends the values of field `name` of the particles `which` (in that order) to `out`
  /// (which.size() x its bytes_per_particle()). Throws std::out_of_range for an unknown field.
  void pack_field(std::string_view name, std::span<const Index> which, std::vector<std::byte>& out) const {
    const std::size_t at = out.size();
    out.resize(at + which.size() * layout_of(name).bytes_per_particle());
    with_field(
        *this, name, [&](const auto& v) { detail::pack_values(v, which, out.data() + at); },
        [&](const detail::FieldBase& f) { f.pack(which, out.data() + at); });
  }
  /// Sets field `name` of particles first .. first + count - 1 from `bytes` (count x its bytes per particle;
  /// std::invalid_argument otherwise, std::out_of_range for an unknown field or particles past the end).
  void unpack_field(std::string_view name, Index first, std::span<const std::byte> bytes) {
    const std::size_t bpp = layout_of(name).bytes_per_particle();
    const std::size_t count = bytes.size() / bpp;
    if (count * bpp != bytes.size())
      throw std::invalid_argument("particle field '" + std::string(name) + "': " + std::to_string(bytes.size()) +
                                  " bytes are not a whole number of particles of " + std::to_string(bpp) + " bytes");
    if (first < 0 || static_cast<std::size_t>(first) + count > static_cast<std::size_t>(size()))
      throw std::out_of_range("particle field '" + std::string(name) + "': particles beyond the set");
    with_field(
        *this, name, [&](auto& v) { detail::unpack_values(v, first, count, bytes.data()); },
        [&](detail::FieldBase& f) { f.unpack(first, count, bytes.data()); });
  }
  /// Appends every field of the particles `which` to `out`, field after field in field_layout() order: what
  /// append_packed() of a set with the same layout reads (particle migration).
  void pack(std::span<const Index> which, std::vector<std::byte>& out) const {
    for (const auto& f : field_layout()) pack_field(f.name, which, out);
  }
  /// Appends `count` particles packed by pack() of a set with the same layout; returns the bytes read.
  /// Throws std::invalid_argument, and appends nothing, when `in` is shorter than that.
  std::size_t append_packed(std::span<const std::byte> in, Index count) {
    const auto layout = field_layout();
    std::size_t total = 0;
    for (const auto& f : layout) total += static_cast<std::size_t>(count) * f.bytes_per_particle();
    if (total > in.size()) throw std::invalid_argument("append_packed: the buffer is shorter than the particles");
    const Index first = size();
    resize(first + count);
    std::size_t at = 0;
    for (const auto& f : layout) {
      const std::size_t n = static_cast<std::size_t>(count) * f.bytes_per_particle();
      unpack_field(f.name, first, in.subspan(at, n));
      at += n;
    }
    return at;
  }
  /// Sets the number of particles; new ones get each on-demand field's initial value and zeros in the core
  /// fields (fill them, e.g. with unpack_field).
  void resize(Index n) {
    const auto count = static_cast<std::size_t>(n);
    x.resize(count, VecU<Dim>::Zero());
    v.resize(count, VecU<Dim>::Zero());
    mass.resize(count, 0);
    volume0.resize(count, 0);
    F.resize(count, MatU<Dim>::Identity());
    stress.resize(count, SymTensor<Dim>{});
    id.resize(count, 0);
    for (auto& [name, f] : extra_) f->resize(count);
    generation_.bump();
  }

 private:
  /// fn(name, vector) for each core field, in field_layout() order (Self: ParticleSet or const ParticleSet).
  template <class Self, class Fn>
  static void visit_core_fields(Self& self, Fn&& fn) {
    fn("position", self.x);
    fn("velocity", self.v);
    fn("mass", self.mass);
    fn("reference_volume", self.volume0);
    fn("deformation_gradient", self.F);
    fn("stress", self.stress);
    fn("id", self.id);
  }
  template <class Fn>
  void for_each_core_field(Fn&& fn) const {
    visit_core_fields(*this, std::forward<Fn>(fn));
  }
  /// Calls core(vector) for a core field, extra(FieldBase) for an on-demand one; std::out_of_range otherwise.
  template <class Self, class Core, class Extra>
  static void with_field(Self& self, std::string_view name, Core&& core, Extra&& extra) {
    bool found = false;
    visit_core_fields(self, [&](std::string_view n, auto& vec) {
      if (found || n != name) return;
      found = true;
      core(vec);
    });
    if (found) return;
    const auto it = self.extra_.find(name);
    if (it == self.extra_.end())
      throw std::out_of_range("particle field '" + std::string(name) + "' was not allocated");
    extra(*it->second);
  }
  FieldLayout layout_of(std::string_view name) const {
    for (const auto& f : field_layout())
      if (f.name == name) return f;
    throw std::out_of_range("particle field '" + std::string(name) + "' was not allocated");
  }
  template <class T>
  static detail::TypedField<T>& typed(detail::FieldBase* f, std::string_view name) {
    auto* t = dynamic_cast<detail::TypedField<T>*>(f);
    if (!t) throw std::logic_error("particle field '" + std::string(name) + "' has another type");
    return *t;
  }
  std::map<std::string, std::unique_ptr<detail::FieldBase>, std::less<>> extra_;  ///< by name (ordered as strings)
  detail::StorageGeneration generation_;
};

}  // namespace mpm
