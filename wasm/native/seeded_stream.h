// Seeded random numbers, the same streams as bench-node/prng.ts: one stream per (seed, name), so
// the native tools draw the very numbers the benchmark command line draws.
#pragma once

#include <cstdint>
#include <string>

namespace ik {

// mulberry32: a small 32-bit generator; operator() returns numbers in [0, 1).
class Mulberry32 {
 public:
  explicit Mulberry32(std::uint32_t seed) : state_(seed) {}

  double operator()() {
    state_ += 0x6d2b79f5u;
    std::uint32_t t = state_;
    t = (t ^ (t >> 15)) * (t | 1u);
    t ^= t + (t ^ (t >> 7)) * (t | 61u);
    return static_cast<double>(t ^ (t >> 14)) / 4294967296.0;
  }

 private:
  std::uint32_t state_;
};

// FNV-1a hash of `text` (bytes; the names hashed are ASCII, as in prng.ts's UTF-16 code units).
inline std::uint32_t hash32(const std::string& text) {
  std::uint32_t h = 0x811c9dc5u;
  for (unsigned char c : text) {
    h ^= c;
    h *= 0x01000193u;
  }
  return h;
}

// The generator of the stream `name` of a run seeded with `seed`.
inline Mulberry32 stream_for(std::uint32_t seed, const std::string& name) {
  return Mulberry32(hash32(std::to_string(seed) + ":" + name));
}

// Uniform in [-1, 1) from a number `unit` in [0, 1).
inline double signed_unit(double unit) { return 2 * unit - 1; }

}  // namespace ik
