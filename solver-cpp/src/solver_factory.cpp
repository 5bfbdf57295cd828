#include "field_solver.hpp"
#include "mg_pcg_solver.hpp"

// The reference "cg" solver is written on main; this branch builds without it (the lead keeps
// the include at merge).
#if __has_include("cg_solver.hpp")
#include "cg_solver.hpp"
#define HAIRSKETCH_HAS_CG 1
#endif

namespace hairsketch {

std::unique_ptr<FieldSolver> makeFieldSolver(const std::string& name) {
#ifdef HAIRSKETCH_HAS_CG
  if (name == "cg") return std::make_unique<CgSolver>();
#endif
  if (name == "fast") return std::make_unique<MgPcgSolver>();
  return nullptr;
}

}  // namespace hairsketch
