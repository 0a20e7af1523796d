#pragma once
// An optimizer's whole state as bytes (Optimizer::save/load): numbers written bit for bit,
// so a state read back continues exactly as the one written. Integers and doubles are
// stored in the machine's byte order (every platform esc builds on is little-endian; the
// store checksums the blob and records the format, so a foreign one is refused, not
// misread). A read past the end or a count that cannot fit throws std::invalid_argument.
#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace esc::evo {

using StateBytes = std::vector<std::uint8_t>;

class StateWriter {
 public:
  // Room for a state's header from the start: GCC 12 at -O3 warns (-Wstringop-overflow, a
  // false positive) on the first insert into an empty vector once inlined.
  StateWriter() { bytes_.reserve(64); }

  template <class T>
    requires std::is_arithmetic_v<T>
  void put(T v) {
    const auto* p = reinterpret_cast<const std::uint8_t*>(&v);
    bytes_.insert(bytes_.end(), p, p + sizeof v);
  }
  void put(std::span<const double> v) {
    put(static_cast<std::uint64_t>(v.size()));
    for (const double d : v) put(d);
  }
  void put(const std::string& s) {
    put(static_cast<std::uint64_t>(s.size()));
    bytes_.insert(bytes_.end(), s.begin(), s.end());
  }
  // Another state inside this one, as put(std::string) writes it, without a copy of it as a
  // string: a population's state is the largest thing a run saves.
  void put(std::span<const std::uint8_t> state) {
    put(static_cast<std::uint64_t>(state.size()));
    bytes_.insert(bytes_.end(), state.begin(), state.end());
  }
  [[nodiscard]] StateBytes take() && { return std::move(bytes_); }

 private:
  StateBytes bytes_;
};

class StateReader {
 public:
  explicit StateReader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}

  template <class T>
    requires std::is_arithmetic_v<T>
  T get() {
    T v{};
    std::memcpy(&v, take(sizeof v).data(), sizeof v);
    return v;
  }
  std::vector<double> doubles() {
    const auto n = count(sizeof(double));
    std::vector<double> v(n);
    for (double& d : v) d = get<double>();
    return v;
  }
  std::string text() {
    const auto n = count(1);
    const auto s = take(n);
    return {s.begin(), s.end()};
  }
  // A count of elements of `width` bytes each that the rest of the state can hold.
  std::size_t count(std::size_t width) {
    const auto n = get<std::uint64_t>();
    if (n > (bytes_.size() - at_) / width) throw std::invalid_argument("optimizer state: a count runs past its end");
    return static_cast<std::size_t>(n);
  }
  [[nodiscard]] bool at_end() const noexcept { return at_ == bytes_.size(); }
  // Throws unless everything was read: trailing bytes mean another format.
  void finish() const {
    if (!at_end()) throw std::invalid_argument("optimizer state: bytes left after its end");
  }

 private:
  std::span<const std::uint8_t> take(std::size_t n) {
    if (n > bytes_.size() - at_) throw std::invalid_argument("optimizer state: truncated");
    const auto s = bytes_.subspan(at_, n);
    at_ += n;
    return s;
  }
  std::span<const std::uint8_t> bytes_;
  std::size_t at_ = 0;
};

}  // namespace esc::evo
