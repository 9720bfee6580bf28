#pragma once
// An edge between two vertex indices as one 64-bit key, for hash maps of a
// mesh's edges.
#include <algorithm>
#include <cstdint>

namespace regio::model {

// The directed edge a -> b: edgeKey(b, a) is the same edge seen from the
// triangle on its other side.
inline std::uint64_t edgeKey(int a, int b) { return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b); }

// The undirected edge {a, b}: the lower index first.
inline std::uint64_t undirectedEdgeKey(int a, int b) { return edgeKey(std::min(a, b), std::max(a, b)); }

} // namespace regio::model
