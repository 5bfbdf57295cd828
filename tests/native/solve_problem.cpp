// Native twin of `hairsketch solve` (web/cli/main.ts), for comparing the wasm module with the
// native build on shared fixtures (tests/unit/wasmNative.test.ts):
//   solve_problem PROBLEM.json --out DIR [--solver exact|fast|auto|cg]
// Reads the same PROBLEM.json (web/cli/problem.ts), applies the steps the same way (unset, then
// set; constraints persist; sorted by index, validated and normalised as the wasm binding does),
// and writes DIR/field-<step>.f64 (n x 3 float64, row p = t_p, little-endian as in wasm),
// DIR/steps.jsonl (one line per step: constraint counts and the method) and DIR/problem.json (a
// copy of the input, so that the reader can tell whether the output is stale). ctest runs it on
// tests/fixtures/problem-small.json and problem-edits.json (solver-cpp/CMakeLists.txt).
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "constraints.hpp"
#include "field_solver.hpp"
#include "grid.hpp"

namespace {

// A minimal JSON reader (objects, arrays, numbers, strings without escapes, true/false/null):
// enough for PROBLEM.json. Numbers go through strtod, which rounds correctly as JSON.parse does.
struct Json {
  enum class Type { Null, Bool, Number, String, Array, Object } type = Type::Null;
  double number = 0;
  std::string string;
  std::vector<Json> items;
  std::vector<std::pair<std::string, Json>> members;

  const Json* get(const std::string& key) const {
    for (const auto& m : members)
      if (m.first == key) return &m.second;
    return nullptr;
  }
};

class JsonReader {
 public:
  explicit JsonReader(const std::string& text) : s_(text) {}

  bool parse(Json& out, std::string& error) {
    if (!value(out, 0) || (skip(), i_ != s_.size())) {
      error = "not valid JSON near byte " + std::to_string(i_);
      return false;
    }
    return true;
  }

 private:
  void skip() {
    while (i_ < s_.size() && std::strchr(" \t\r\n", s_[i_]) != nullptr) ++i_;
  }
  bool literal(const char* word) {
    const size_t n = std::strlen(word);
    if (s_.compare(i_, n, word) != 0) return false;
    i_ += n;
    return true;
  }
  bool str(std::string& out) {
    if (s_[i_] != '"') return false;
    const size_t end = s_.find('"', i_ + 1);
    if (end == std::string::npos) return false;
    out = s_.substr(i_ + 1, end - i_ - 1);
    if (out.find('\\') != std::string::npos) return false;
    i_ = end + 1;
    return true;
  }
  bool value(Json& v, int depth) {
    skip();
    if (i_ >= s_.size() || depth > 64) return false;
    const char c = s_[i_];
    if (c == '{') {
      v.type = Json::Type::Object;
      ++i_;
      skip();
      if (i_ < s_.size() && s_[i_] == '}') return ++i_, true;
      for (;;) {
        skip();
        std::string key;
        if (i_ >= s_.size() || !str(key)) return false;
        skip();
        if (i_ >= s_.size() || s_[i_] != ':') return false;
        ++i_;
        v.members.emplace_back(key, Json());
        if (!value(v.members.back().second, depth + 1)) return false;
        skip();
        if (i_ < s_.size() && s_[i_] == ',') {
          ++i_;
          continue;
        }
        if (i_ < s_.size() && s_[i_] == '}') return ++i_, true;
        return false;
      }
    }
    if (c == '[') {
      v.type = Json::Type::Array;
      ++i_;
      skip();
      if (i_ < s_.size() && s_[i_] == ']') return ++i_, true;
      for (;;) {
        v.items.emplace_back();
        if (!value(v.items.back(), depth + 1)) return false;
        skip();
        if (i_ < s_.size() && s_[i_] == ',') {
          ++i_;
          continue;
        }
        if (i_ < s_.size() && s_[i_] == ']') return ++i_, true;
        return false;
      }
    }
    if (c == '"') {
      v.type = Json::Type::String;
      return str(v.string);
    }
    if (literal("true") || literal("false")) {
      v.type = Json::Type::Bool;
      return true;
    }
    if (literal("null")) return true;
    const char* start = s_.c_str() + i_;
    char* end = nullptr;
    errno = 0;
    v.number = std::strtod(start, &end);
    if (end == start || errno == ERANGE) return false;
    v.type = Json::Type::Number;
    i_ += size_t(end - start);
    return true;
  }

  const std::string& s_;
  size_t i_ = 0;
};

bool isInt(const Json& v) {
  return v.type == Json::Type::Number && std::floor(v.number) == v.number &&
         std::fabs(v.number) < 1e9;
}

int fail(const std::string& message) {
  std::fprintf(stderr, "solve_problem: %s\n", message.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace hairsketch;
  const char* usage = "usage: solve_problem PROBLEM.json --out DIR [--solver exact|fast|auto|cg]";
  std::string problemPath, outDir, solverName = "exact";
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if ((arg == "--out" || arg == "--solver") && a + 1 < argc)
      (arg == "--out" ? outDir : solverName) = argv[++a];
    else if (problemPath.empty() && arg.rfind("--", 0) != 0)
      problemPath = arg;
    else
      return fail(usage);
  }
  if (problemPath.empty() || outDir.empty()) return fail(usage);

  std::ifstream in(problemPath, std::ios::binary);
  if (!in) return fail("cannot read " + problemPath);
  std::stringstream buf;
  buf << in.rdbuf();
  const std::string text = buf.str();
  Json doc;
  std::string error;
  if (!JsonReader(text).parse(doc, error)) return fail(problemPath + ": " + error);

  // The problem: {"grid": [nx, ny, nz], "omega": w, "steps": [{"set": [...], "unset": [...]}]}.
  const Json* gridJ = doc.get("grid");
  if (!gridJ || gridJ->items.size() != 3) return fail("\"grid\" must be [nx, ny, nz]");
  int dims[3];
  for (int d = 0; d < 3; ++d) {
    if (!isInt(gridJ->items[size_t(d)]) || gridJ->items[size_t(d)].number < 2)
      return fail("\"grid\" must be [nx, ny, nz], integers >= 2");
    dims[d] = int(gridJ->items[size_t(d)].number);
  }
  Grid grid;
  grid.nx = dims[0];
  grid.ny = dims[1];
  grid.nz = dims[2];
  const Json* omegaJ = doc.get("omega");
  const double omega = omegaJ ? omegaJ->number : 100.0;
  if (omegaJ && (omegaJ->type != Json::Type::Number || !(omega > 0)))
    return fail("\"omega\" must be a number > 0");
  const Json* stepsJ = doc.get("steps");
  if (!stepsJ || stepsJ->type != Json::Type::Array) return fail("\"steps\" must be an array");

  std::unique_ptr<FieldSolver> solver = makeFieldSolver(solverName);
  if (!solver) return fail("unknown solver " + solverName);
  Status st = solver->setGrid(grid, omega);
  if (!st.ok()) return fail("setGrid: " + st.message);

  std::error_code ec;
  std::filesystem::create_directories(outDir, ec);
  if (ec) return fail("cannot create " + outDir + ": " + ec.message());
  std::ofstream(outDir + "/problem.json", std::ios::binary) << text;
  std::ofstream steps(outDir + "/steps.jsonl");

  auto indexOf = [&](const Json& e, int& p) {
    for (int d = 0; d < 3; ++d)
      if (!isInt(e.items[size_t(d)]) || e.items[size_t(d)].number < 0 ||
          e.items[size_t(d)].number >= dims[d])
        return false;
    p = grid.index(int(e.items[0].number), int(e.items[1].number), int(e.items[2].number));
    return true;
  };
  std::map<int, Eigen::Vector3d> current;
  Field T;
  for (size_t s = 0; s < stepsJ->items.size(); ++s) {
    const Json& step = stepsJ->items[s];
    const std::string where = "step " + std::to_string(s);
    if (const Json* unset = step.get("unset"))
      for (const Json& e : unset->items) {
        int p;
        if (e.items.size() != 3 || !indexOf(e, p)) return fail(where + ": bad unset entry");
        current.erase(p);
      }
    if (const Json* set = step.get("set"))
      for (const Json& e : set->items) {
        int p;
        if (e.items.size() != 6 || !indexOf(e, p)) return fail(where + ": bad set entry");
        current[p] = Eigen::Vector3d(e.items[3].number, e.items[4].number, e.items[5].number);
      }
    std::vector<Constraint> raw;
    for (const auto& kv : current) raw.push_back({kv.first, kv.second});
    st = validateConstraints(grid, raw);
    if (!st.ok()) return fail(where + ": " + st.message);
    st = solver->setConstraints(normalizeConstraints(std::move(raw)));
    if (st.ok()) st = solver->solve(T);
    if (!st.ok()) return fail(where + ": " + st.message);

    const std::string file = outDir + "/field-" + std::to_string(s) + ".f64";
    std::ofstream f(file, std::ios::binary);
    f.write(reinterpret_cast<const char*>(T.data()), std::streamsize(T.size() * sizeof(double)));
    if (!f) return fail("cannot write " + file);
    const SolveStats& stats = solver->stats();
    char line[256];
    std::snprintf(line, sizeof line,
                  "{\"step\":%zu,\"constraints\":%zu,\"added\":%d,\"removed\":%d,\"changed\":%d,"
                  "\"method\":\"%s\",\"iterations\":%d}\n",
                  s, current.size(), stats.added, stats.removed, stats.changed,
                  stats.method.c_str(), stats.iterations);
    steps << line;
    std::fputs(line, stdout);
  }
  steps.flush();
  if (!steps) return fail("cannot write " + outDir + "/steps.jsonl");
  return 0;
}
