#pragma once
// The one way Regio's libraries report that input was refused: a function
// that can fail on its input returns Result<T>, either a value (possibly with
// warnings beside it) or the diagnostics that explain why there is none (at
// least one of them an error). Exceptions are kept for programming errors.
//
//   model::Result<model::Scene> read = model::loadSceneFile(path);
//   if (!read)
//       report(read.diagnostics());      // every problem, errors first found first
//   use(*read);                          // read.diagnostics() may hold warnings
//
// [[nodiscard]]: a refused edit or an unwritten file is never ignored by
// accident; callers that really do not care say so with a (void) cast.
#include "model/diagnostic.h"

#include <cassert>
#include <optional>
#include <utility>

namespace regio::model {

struct Unit {
    bool operator==(const Unit&) const = default;
};

template <typename T = Unit>
class [[nodiscard]] Result {
public:
    using value_type = T;

    Result(T value)
        : m_value(std::move(value))
    {
    }
    Result(T value, Diagnostics warnings)
        : m_value(std::move(value))
        , m_diagnostics(std::move(warnings))
    {
    }
    Result(Diagnostic error)
        : m_diagnostics{std::move(error)}
    {
    }
    // A failure: `diagnostics` must hold at least one error.
    Result(Diagnostics diagnostics)
        : m_diagnostics(std::move(diagnostics))
    {
        assert(hasErrors(m_diagnostics));
    }

    // The failure of another result, passed on (its warnings and errors).
    template <typename U>
    static Result failureOf(const Result<U>& other)
    {
        assert(!other.ok());
        return Result(other.diagnostics());
    }

    bool ok() const { return m_value.has_value(); }
    explicit operator bool() const { return ok(); }

    T& value() & { return *m_value; }
    const T& value() const& { return *m_value; }
    T&& value() && { return std::move(*m_value); }
    T* operator->() { return &*m_value; }
    const T* operator->() const { return &*m_value; }
    T& operator*() & { return *m_value; }
    const T& operator*() const& { return *m_value; }
    T&& operator*() && { return std::move(*m_value); }

    // The first error of a failure (only meaningful when !ok()).
    const Diagnostic& error() const
    {
        for (const Diagnostic& d : m_diagnostics)
            if (d.isError())
                return d;
        assert(!m_diagnostics.empty());
        return m_diagnostics.front();
    }

    // Warnings beside a value, or everything a failure found.
    const Diagnostics& diagnostics() const { return m_diagnostics; }
    Diagnostics takeDiagnostics() { return std::move(m_diagnostics); }

private:
    std::optional<T> m_value;
    Diagnostics m_diagnostics;
};

// The check of a value: nothing, or the problem with it.
using Check = Result<Unit>;
inline Check success() { return Unit{}; }

} // namespace regio::model
