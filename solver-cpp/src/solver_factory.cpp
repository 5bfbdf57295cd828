#include "exact_solver.hpp"
#include "field_solver.hpp"
// The CG solver lands on main separately; until this branch is merged with it, build without it.
#if __has_include("cg_solver.hpp")
#include "cg_solver.hpp"
#define HAIRSKETCH_HAS_CG 1
#endif

namespace hairsketch {

std::unique_ptr<FieldSolver> makeFieldSolver(const std::string& name) {
#ifdef HAIRSKETCH_HAS_CG
  if (name == "cg") return std::make_unique<CgSolver>();
#endif
  if (name == "exact") return std::make_unique<ExactSolver>();
  return nullptr;
}

}  // namespace hairsketch
