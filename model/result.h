#pragma once
// Result of a model edit: a value or the diagnostic that explains why the
// edit was refused. The scene is left unchanged whenever an edit fails.
#include "model/diagnostic.h"

#include <utility>
#include <variant>

namespace regio::model {

struct Unit {};

template <typename T = Unit>
class Result {
public:
    Result(T value) : m_state(std::move(value)) {}
    Result(Diagnostic error) : m_state(std::move(error)) {}

    bool ok() const { return std::holds_alternative<T>(m_state); }
    explicit operator bool() const { return ok(); }

    T& value() { return std::get<T>(m_state); }
    const T& value() const { return std::get<T>(m_state); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() { return value(); }
    const T& operator*() const { return value(); }

    const Diagnostic& error() const { return std::get<Diagnostic>(m_state); }

private:
    std::variant<T, Diagnostic> m_state;
};

} // namespace regio::model
