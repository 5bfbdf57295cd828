#include "auto_solver.hpp"
#include "cg_solver.hpp"
#include "exact_solver.hpp"
#include "field_solver.hpp"
#include "mg_pcg_solver.hpp"

namespace hairsketch {

std::unique_ptr<FieldSolver> makeFieldSolver(const std::string& name) {
  if (name == "cg") return std::make_unique<CgSolver>();
  if (name == "fast") return std::make_unique<MgPcgSolver>();
  if (name == "exact") return std::make_unique<ExactSolver>();
  if (name == "auto") return std::make_unique<AutoSolver>();
  return nullptr;
}

}  // namespace hairsketch
