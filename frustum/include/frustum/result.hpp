// Result<T>: a value or an Error. No exceptions cross the library boundary
// and nothing asserts on user data; callers decide what to print.
//
// Reading the value of a failed result (value(), *, ->) or the error of a
// successful one (take_error()) is a programming error in the caller, not bad
// user data: it prints one line to stderr and aborts, with or without
// exceptions (FRUSTUM_NO_EXCEPTIONS), in every build type. Test ok() first,
// or use value_or().
//
//   auto pair = frustum::perspective<float>(fovy, aspect, near_m, far_m, depth);
//   if (!pair) {
//       return pair.take_error_in("render::main_camera()"); // "render::main_camera(): frustum::perspective(): ..."
//   }
//   use(*pair);
#pragma once

#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

namespace frustum {

// One error format for the whole project:
//   "frustum::perspective(): near must be > 0, got near=-0.1 far=100"
// i.e. qualified function name, the broken rule, every value involved.
struct Error {
    std::string message;
};

namespace detail {

// The one place a misused Result stops the program: `what` names the misuse,
// `message` is the error the result held (empty when it held a value).
[[noreturn]] inline void result_misuse(const char* what, const std::string& message) {
    std::fprintf(stderr, "frustum::Result: %s%s%s\n", what, message.empty() ? "" : ": ", message.c_str());
    std::fflush(stderr);
    std::abort();
}

// "caller: message" (the caller's name first, as in the project's format).
inline Error prefixed(std::string_view caller, std::string message) {
    std::string text(caller);
    text += ": ";
    text += message;
    return Error{std::move(text)};
}

} // namespace detail

template <class T>
class [[nodiscard]] Result {
public:
    Result(T value) : state_(std::in_place_index<0>, std::move(value)) {} // NOLINT: implicit by design
    Result(Error error) : state_(std::in_place_index<1>, std::move(error)) {} // NOLINT: implicit by design
    // The value built in place from its constructor's arguments.
    template <class... Args>
    explicit Result(std::in_place_t, Args&&... args) : state_(std::in_place_index<0>, std::forward<Args>(args)...) {}

    bool ok() const { return state_.index() == 0; }
    explicit operator bool() const { return ok(); }

    // Precondition: ok(); aborts with the held error otherwise.
    const T& value() const& { return *checked(); }
    T& value() & { return *checked(); }
    T&& value() && { return std::move(*checked()); }
    const T& operator*() const& { return value(); }
    T& operator*() & { return value(); }
    T&& operator*() && { return std::move(*checked()); }
    const T* operator->() const { return checked(); }
    T* operator->() { return checked(); }

    // The value, or `fallback` when failed (never aborts).
    template <class U>
    T value_or(U&& fallback) const& {
        return ok() ? *std::get_if<0>(&state_) : static_cast<T>(std::forward<U>(fallback));
    }
    template <class U>
    T value_or(U&& fallback) && {
        return ok() ? std::move(*std::get_if<0>(&state_)) : static_cast<T>(std::forward<U>(fallback));
    }

    // Empty when ok().
    const std::string& error() const {
        static const std::string none;
        const Error* e = std::get_if<1>(&state_);
        return e ? e->message : none;
    }

    // Precondition: !ok(). The error, to return as is from a function of
    // another Result type: `if (!x) return x.take_error();`. Moved out of a
    // non-const result (whose error() is then empty), copied from a const one.
    Error take_error() { return Error{std::move(failed()->message)}; }
    Error take_error() const { return Error{failed()->message}; }
    // The same with the caller's name in front: "caller: <error>".
    Error take_error_in(std::string_view caller) { return detail::prefixed(caller, std::move(failed()->message)); }
    Error take_error_in(std::string_view caller) const { return detail::prefixed(caller, failed()->message); }

private:
    const T* checked() const {
        const T* v = std::get_if<0>(&state_);
        if (v == nullptr) {
            detail::result_misuse("value() of a failed result", error());
        }
        return v;
    }
    T* checked() { return const_cast<T*>(static_cast<const Result&>(*this).checked()); }
    const Error* failed() const {
        const Error* e = std::get_if<1>(&state_);
        if (e == nullptr) {
            detail::result_misuse("take_error() of a successful result", std::string());
        }
        return e;
    }
    Error* failed() { return const_cast<Error*>(static_cast<const Result&>(*this).failed()); }

    // A variant, not optional + string: a successful result carries no
    // string at all, which keeps the hot paths (crop, clip) lean.
    std::variant<T, Error> state_;
};

// A Result with no value: success or an Error.
class [[nodiscard]] Status {
public:
    Status() = default;
    Status(Error error) : error_(std::move(error)) {} // NOLINT: implicit by design
    bool ok() const { return !error_.has_value(); }
    explicit operator bool() const { return ok(); }
    // Empty when ok().
    const std::string& error() const {
        static const std::string none;
        return error_ ? error_->message : none;
    }
    // Precondition: !ok(), as Result::take_error() / take_error_in().
    Error take_error() { return Error{std::move(failed().message)}; }
    Error take_error() const { return Error{failed().message}; }
    Error take_error_in(std::string_view caller) { return detail::prefixed(caller, std::move(failed().message)); }
    Error take_error_in(std::string_view caller) const { return detail::prefixed(caller, failed().message); }

private:
    const Error& failed() const {
        if (!error_) {
            detail::result_misuse("take_error() of a successful status", std::string());
        }
        return *error_;
    }
    Error& failed() { return const_cast<Error&>(static_cast<const Status&>(*this).failed()); }
    std::optional<Error> error_; // no string at all on success
};

} // namespace frustum
