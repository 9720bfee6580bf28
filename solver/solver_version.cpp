// Placeholder translation unit so the solver library exists before its first
// real source lands; removed when the solver pipeline is added.
namespace regio::solver {
const char* version() { return "0.1.0"; }
} // namespace regio::solver
