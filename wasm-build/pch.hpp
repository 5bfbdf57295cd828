// Headers most of the core's files include, parsed once per module variant (build.sh compiles
// this into a precompiled header and every object starts from it); what the code means is the
// same without it.
#pragma once
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>
