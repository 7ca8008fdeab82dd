#pragma once
// Byte streams of a solver's or run loop's state, for checkpoints (pipeline/Checkpoint.h).
// Values are stored in the machine's own byte order and sizes (a checkpoint is read back by the
// same build on the same machine to continue a run bit-identically; it is not an exchange format).
// Every read is bounds-checked: a short or malformed stream throws StateFormatError, which the
// checkpoint reader reports as a corrupt file.
//
//   StateWriter w;  w.put<std::int64_t>(steps);  w.putVector(rho);
//   StateReader r(w.bytes());  steps = r.get<std::int64_t>();  r.getVector(rho, expectedCount);
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "fieldviz/core/Field.h"

namespace fluidviz {

/// A state stream that does not hold what its reader expects.
class StateFormatError : public std::runtime_error {
  using std::runtime_error::runtime_error;
};

class StateWriter {
 public:
  template <class T>
  void put(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    putBytes(&value, sizeof(T));
  }
  void putBytes(const void* data, std::size_t size) {
    const auto* p = static_cast<const std::uint8_t*>(data);
    bytes_.insert(bytes_.end(), p, p + size);
  }
  void putString(const std::string& s) {
    put<std::uint64_t>(s.size());
    putBytes(s.data(), s.size());
  }
  /// Count, then the values.
  template <class T>
  void putVector(const std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    put<std::uint64_t>(v.size());
    putBytes(v.data(), v.size() * sizeof(T));
  }
  void putVec3s(const std::vector<Vec3>& v) {
    put<std::uint64_t>(v.size());
    for (const Vec3& x : v) putBytes(x.data(), 3 * sizeof(double));
  }
  void putStrings(const std::vector<std::string>& v) {
    put<std::uint64_t>(v.size());
    for (const std::string& s : v) putString(s);
  }

  const std::vector<std::uint8_t>& bytes() const { return bytes_; }
  std::vector<std::uint8_t>& bytes() { return bytes_; }

 private:
  std::vector<std::uint8_t> bytes_;
};

class StateReader {
 public:
  StateReader() = default;
  explicit StateReader(std::vector<std::uint8_t> bytes, std::size_t offset = 0)
      : bytes_(std::move(bytes)), at_(offset) {}

  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    T value;
    getBytes(&value, sizeof(T));
    return value;
  }
  void getBytes(void* out, std::size_t size) {
    need(size);
    // An empty vector's data() may be null, and memcpy from/to null is undefined even for 0
    // bytes (UBSan, scripts/sanitize.sh).
    if (size > 0) std::memcpy(out, bytes_.data() + at_, size);
    at_ += size;
  }
  std::string getString() {
    const std::uint64_t n = count(1);
    std::string s(reinterpret_cast<const char*>(bytes_.data() + at_), n);
    at_ += n;
    return s;
  }
  /// Reads a vector; `expected` (if not -1) is the count the reader's own state requires.
  template <class T>
  void getVector(std::vector<T>& v, std::int64_t expected = -1) {
    const std::uint64_t n = count(sizeof(T));
    requireCount(n, expected);
    v.resize(n);
    getBytes(v.data(), n * sizeof(T));
  }
  void getVec3s(std::vector<Vec3>& v, std::int64_t expected = -1) {
    const std::uint64_t n = count(3 * sizeof(double));
    requireCount(n, expected);
    v.resize(n);
    for (Vec3& x : v) getBytes(x.data(), 3 * sizeof(double));
  }
  std::vector<std::string> getStrings() {
    const std::uint64_t n = count(sizeof(std::uint64_t));
    std::vector<std::string> v;
    for (std::uint64_t k = 0; k < n; ++k) v.push_back(getString());
    return v;
  }
  /// Throws unless `actual` equals `expected`: a state written for another configuration.
  template <class T>
  static void requireSame(const char* what, const T& actual, const T& expected) {
    if (actual != expected)
      throw StateFormatError(std::string(what) + " is " + std::to_string(actual) +
                             " in the saved state but " + std::to_string(expected) + " here");
  }

  std::size_t remaining() const { return bytes_.size() - at_; }
  std::size_t offset() const { return at_; }

 private:
  void need(std::size_t size) const {
    if (size > remaining())
      throw StateFormatError("the state ends early (" + std::to_string(remaining()) +
                             " bytes left at offset " + std::to_string(at_) + ", " +
                             std::to_string(size) + " needed)");
  }
  // A count followed by that many items of itemSize bytes, checked against what is left before
  // anything is allocated.
  std::uint64_t count(std::size_t itemSize) {
    const auto n = get<std::uint64_t>();
    if (itemSize > 0 && n > remaining() / itemSize)
      throw StateFormatError("a count of " + std::to_string(n) + " items at offset " +
                             std::to_string(at_) + " exceeds the " +
                             std::to_string(remaining()) + " bytes left");
    return n;
  }
  static void requireCount(std::uint64_t n, std::int64_t expected) {
    if (expected >= 0 && n != static_cast<std::uint64_t>(expected))
      throw StateFormatError("an array holds " + std::to_string(n) + " values in the saved state "
                             "but " + std::to_string(expected) + " here");
  }

  std::vector<std::uint8_t> bytes_;
  std::size_t at_ = 0;
};

}  // namespace fluidviz
