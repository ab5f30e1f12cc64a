// Result<T, E>: a value or an error, with std::expected's names so that the
// move to C++23 is a rename. No exceptions on facet's compiler paths.
#pragma once

#include <cstdlib>
#include <cstdio>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>

namespace facet {

// The default error of compiler stages: the details are diagnostics that the
// stage already wrote into the Diagnostics it was given; `reason` is a short
// summary for callers that only want a line.
struct Failure {
  std::string reason;
};

template <typename E>
struct Unexpected {
  E error;
};

template <typename E>
Unexpected<std::decay_t<E>> unexpected(E&& e) {
  return {std::forward<E>(e)};
}

inline Unexpected<Failure> failure(std::string reason = {}) { return {Failure{std::move(reason)}}; }

[[noreturn]] inline void internal_compiler_error(const char* what, const char* file, int line) {
  std::fprintf(stderr, "facet: internal compiler error: %s (%s:%d)\n", what, file, line);
  std::abort();
}

// A broken internal invariant: prints and aborts (fuzzers find these).
#define FACET_ICE(what) ::facet::internal_compiler_error((what), __FILE__, __LINE__)

template <typename T, typename E = Failure>
class [[nodiscard]] Result {
 public:
  using value_type = T;
  using error_type = E;

  Result(const T& v) : data_(std::in_place_index<0>, v) {}
  Result(T&& v) : data_(std::in_place_index<0>, std::move(v)) {}
  template <typename G>
  Result(Unexpected<G> u) : data_(std::in_place_index<1>, E(std::move(u.error))) {}

  bool has_value() const { return data_.index() == 0; }
  explicit operator bool() const { return has_value(); }

  T& value() & { check_value(); return std::get<0>(data_); }
  const T& value() const& { check_value(); return std::get<0>(data_); }
  T&& value() && { check_value(); return std::get<0>(std::move(data_)); }
  const E& error() const {
    if (has_value()) FACET_ICE("Result::error() on a value");
    return std::get<1>(data_);
  }

  T& operator*() & { return value(); }
  const T& operator*() const& { return value(); }
  T&& operator*() && { return std::move(*this).value(); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }

 private:
  void check_value() const {
    if (!has_value()) FACET_ICE("Result::value() on an error");
  }
  std::variant<T, E> data_;
};

// Result<void>: success or an error.
template <typename E>
class [[nodiscard]] Result<void, E> {
 public:
  Result() = default;
  template <typename G>
  Result(Unexpected<G> u) : error_(E(std::move(u.error))), ok_(false) {}
  bool has_value() const { return ok_; }
  explicit operator bool() const { return ok_; }
  const E& error() const {
    if (ok_) FACET_ICE("Result::error() on a value");
    return error_;
  }

 private:
  E error_{};
  bool ok_ = true;
};

// Propagates a failed Result out of the enclosing function, which must return
// a Result with the same error type.
#define FACET_TRY(expr)                                             \
  do {                                                              \
    auto&& facet_try_result_ = (expr);                              \
    if (!facet_try_result_) return ::facet::unexpected(facet_try_result_.error()); \
  } while (0)

}  // namespace facet
