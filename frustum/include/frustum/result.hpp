// Result<T>: a value or an Error. No exceptions cross the library boundary
// and nothing asserts on user data; callers decide what to print.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <variant>

namespace frustum {

// One error format for the whole project:
//   "frustum::perspective(): near must be > 0, got near=-0.1 far=100"
// i.e. qualified function name, the broken rule, every value involved.
struct Error {
    std::string message;
};

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

    // Precondition: ok(). Reading the value of a failed result is a
    // programming error in the caller, not bad user data.
    const T& value() const& { return *std::get_if<0>(&state_); }
    T& value() & { return *std::get_if<0>(&state_); }
    T&& value() && { return std::move(*std::get_if<0>(&state_)); }
    const T& operator*() const& { return value(); }
    T& operator*() & { return value(); }
    const T* operator->() const { return std::get_if<0>(&state_); }
    T* operator->() { return std::get_if<0>(&state_); }

    // Empty when ok().
    const std::string& error() const {
        static const std::string none;
        const Error* e = std::get_if<1>(&state_);
        return e ? e->message : none;
    }

private:
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

private:
    std::optional<Error> error_; // no string at all on success
};

} // namespace frustum
