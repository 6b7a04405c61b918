#pragma once
/// \file exact_sum.hpp
/// A correctly rounded sum of doubles: the result is the exact sum rounded once (to nearest, ties to even),
/// so it does not depend on the order of the terms. Histories (reactions, region sums), the energy audit
/// (energy.hpp) and the contact forces use it so that a number is the same for any thread count, any particle
/// order and, later, any number of ranks: partial sums merged (merge()) give the bits of one sum over all the
/// terms.
///
/// How: every finite double is an integer multiple of 2^-1074 below 2^1024, so the sum is held exactly as one
/// long fixed-point integer (a "superaccumulator", Kulisch; the chunked form of R. M. Neal, "Fast exact
/// summation using small and large superaccumulators", arXiv:1505.05571, 2015): 32-bit digits, each kept in
/// a signed 64-bit word so that a term adds its 53-bit mantissa to three words without carrying. The carries
/// are propagated only when value() is read or after 2^30 terms. A term costs a few integer operations and no
/// branch on its value (Shewchuk's partials, used here before, cost 250 ns a term on random data: too slow for
/// an energy audit of a million particles).

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>

namespace mpm {

class ExactSum {
 public:
  /// Adds x exactly (inf and NaN propagate as in an ordinary sum).
  void add(double x) {
    const auto bits = std::bit_cast<std::uint64_t>(x);
    const int biased = static_cast<int>((bits >> 52) & 0x7ff);
    if (biased == 0x7ff) {  // inf/NaN: the ordinary sum propagates them
      special_ += x;
      return;
    }
    // |x| = mantissa * 2^(position - 1074); subnormals have the exponent of the smallest normal numbers.
    const std::uint64_t mantissa = (bits & ((std::uint64_t{1} << 52) - 1)) | (biased ? std::uint64_t{1} << 52 : 0);
    const int position = biased ? biased - 1 : 0;
    const unsigned __int128 shifted = static_cast<unsigned __int128>(mantissa) << (position & 31);
    const std::int64_t sign = static_cast<std::int64_t>(bits >> 63);  // 0 or 1
    const int c = position >> 5;
    // +v or -v without a branch: (v ^ -sign) + sign
    auto apply = [sign](std::uint64_t v) { return (static_cast<std::int64_t>(v) ^ -sign) + sign; };
    digit_[c] += apply(static_cast<std::uint64_t>(shifted) & digit_mask);
    digit_[c + 1] += apply(static_cast<std::uint64_t>(shifted >> 32) & digit_mask);
    digit_[c + 2] += apply(static_cast<std::uint64_t>(shifted >> 64));
    if (++terms_ == carry_interval) carry();
  }
  ExactSum& operator+=(double x) {
    add(x);
    return *this;
  }
  /// Adds every term of `o`: the result is the exact sum of both sets of terms.
  void merge(const ExactSum& o) {
    ExactSum other = o;
    other.carry();
    carry();
    for (int c = 0; c < digits; ++c) digit_[c] += other.digit_[c];
    terms_ = 2;
    special_ += o.special_;
  }
  /// The exact sum rounded to the nearest double (ties to even); 0 for no term, +-inf beyond the range.
  double value() const {
    if (special_ != 0 || std::isnan(special_)) return special_;
    ExactSum n = *this;
    n.carry();  // digits 0 .. digits-2 in [0, 2^32), the sign in the top one
    const bool negative = n.digit_[digits - 1] < 0;
    if (negative) {
      for (auto& d : n.digit_) d = -d;
      n.carry();
    }
    int h = digits - 1;  // the highest non-zero digit
    while (h >= 0 && n.digit_[h] == 0) --h;
    if (h < 0) return 0;
    auto digit = [&](int c) { return c >= 0 ? static_cast<std::uint64_t>(n.digit_[c]) : std::uint64_t{0}; };
    // The top 65-96 bits (digits h, h-1, h-2), and whether anything lies below them.
    const unsigned __int128 window =
        (static_cast<unsigned __int128>(digit(h)) << 64) | (digit(h - 1) << 32) | digit(h - 2);
    bool sticky = false;
    for (int c = 0; c < h - 2; ++c) sticky = sticky || n.digit_[c] != 0;
    const int length = 64 + (64 - std::countl_zero(digit(h)));  // bits in the window
    const int drop = length - 53;                               // 12 .. 43
    auto mantissa = static_cast<std::uint64_t>(window >> drop);
    const auto rest = static_cast<std::uint64_t>(window & ((static_cast<unsigned __int128>(1) << drop) - 1));
    const std::uint64_t half = std::uint64_t{1} << (drop - 1);
    if (rest > half || (rest == half && (sticky || (mantissa & 1)))) ++mantissa;  // to nearest, ties to even
    // Exact below 2^53 (rest is then zero), correctly rounded above; ldexp is exact unless it overflows.
    const double magnitude = std::ldexp(static_cast<double>(mantissa), drop + 32 * (h - 2) - 1074);
    return negative ? -magnitude : magnitude;
  }
  void clear() { *this = ExactSum(); }

  static constexpr int digits = 70;  ///< 32-bit digits from 2^-1074: 2^1166 > 2^30 terms of 2^1024
  using Digits = std::array<std::int64_t, digits>;
  /// The digits after carrying (digits 0..68 in [0, 2^32), the sign in the top one): what an allreduce adds
  /// across ranks (MPI_SUM on int64, no overflow below 2^31 ranks); the inf/NaN part is summed apart.
  Digits carried_digits() const {
    ExactSum n = *this;
    n.carry();
    return n.digit_;
  }
  double special() const { return special_; }
  /// The sum whose digits (as carried_digits() gives, or sums of them) and inf/NaN part are these.
  static ExactSum from_digits(const Digits& d, double special) {
    ExactSum s;
    s.digit_ = d;
    s.special_ = special;
    s.carry();  // a sum of up to 2^31 carried sets is below 2^63 per word; carried, it takes 2^30 terms more
    return s;
  }

 private:
  static constexpr std::uint64_t digit_mask = 0xffffffffu;
  static constexpr std::int64_t carry_interval = std::int64_t{1} << 30;  ///< terms before a word could overflow

  /// Moves every digit's excess to the next: digits 0 .. digits-2 end in [0, 2^32).
  void carry() {
    for (int c = 0; c + 1 < digits; ++c) {
      const std::int64_t up = digit_[c] >> 32;  // floor division by 2^32
      digit_[c] -= up * (std::int64_t{1} << 32);
      digit_[c + 1] += up;
    }
    terms_ = 0;
  }

  std::array<std::int64_t, digits> digit_{};
  std::int64_t terms_ = 0;
  double special_ = 0;
};

}  // namespace mpm
