// Every solver (and the engine) refuses a grid past the memory cap before allocating, with
// OverMemoryCap and "over the memory cap (needs ~X MB, cap Y MB)".
#include <gtest/gtest.h>

#include <string>

#include "field_solver.hpp"
#include "hair_engine.hpp"
#include "memory_budget.hpp"

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace memory_cap_test {

using namespace hairsketch;

namespace {
Grid dims(int nx, int ny, int nz) {
  Grid g;
  g.nx = nx;
  g.ny = ny;
  g.nz = nz;
  return g;
}
}  // namespace

TEST(MemoryCap, BigGridsAreRefusedByEverySolverWithTheFigures) {
  // 158^3 (3.9M points) and 2 x 2 x 10^6: measured aborts of the wasm module before the cap.
  for (const Grid& g : {dims(158, 158, 158), dims(2, 2, 1000000)})
    for (const char* name : {"exact", "fast", "auto"}) {
      auto s = makeFieldSolver(name);
      const Status st = s->setGrid(g, 100);
      EXPECT_EQ(st.code, StatusCode::OverMemoryCap) << name << ": " << st.message;
      EXPECT_NE(st.message.find("over the memory cap (needs ~"), std::string::npos) << st.message;
      EXPECT_NE(
          st.message.find(" MB, cap " + std::to_string(availableMemoryBytes() >> 20) + " MB)"),
          std::string::npos)
          << st.message;
    }
  // CG fits both (288 bytes a point), and is refused under a smaller cap.
  auto cg = makeFieldSolver("cg");
  EXPECT_LT(cg->estimateBytes(dims(158, 158, 158)), double(availableMemoryBytes()));
  cg->setMemoryCap(int64_t(512) << 20);
  EXPECT_EQ(cg->setGrid(dims(158, 158, 158), 100).code, StatusCode::OverMemoryCap);
}

TEST(MemoryCap, DimsPastTheIndexRangeAreRefusedWithoutOverflow) {
  for (const char* name : {"exact", "fast", "auto", "cg"}) {
    for (const Grid& g : {dims(2, 2, 1000000000), dims(2000000, 2000000, 2000000)}) {
      auto s = makeFieldSolver(name);
      s->setMemoryCap(int64_t(1) << 62);  // only the index range stops it
      const Status st = s->setGrid(g, 100);
      EXPECT_EQ(st.code, StatusCode::OverMemoryCap) << name << ": " << st.message;
      EXPECT_GT(s->estimateBytes(g), double(int64_t(1) << 31)) << name;
    }
  }
}

TEST(MemoryCap, EngineRefusesTheSameWay) {
  HairEngine e;
  Grid g = dims(158, 158, 158);
  g.step = 0.01;
  const Status st = e.setGrid(g, 100, "fast");
  EXPECT_EQ(st.code, StatusCode::OverMemoryCap);
  EXPECT_NE(st.message.find("fast solver: over the memory cap (needs ~"), std::string::npos)
      << st.message;
  // A grid that fits still works after a refusal.
  Grid small = dims(8, 8, 8);
  small.step = 0.1;
  EXPECT_TRUE(e.setGrid(small, 100, "fast").ok());
}

}  // namespace memory_cap_test
