#pragma once

namespace hairsketch {

// Value noise in [0, 1) over world space: seeded values at the corners of kRootNoiseCell cells,
// blended trilinearly, so roots close together get close values (a root and its mirror twin, a
// fraction of a millimetre apart, agree) while roots a few cells apart vary independently. Growth
// reads it at a strand's root (x taken from the head's middle, so both sides agree) for the
// strand's own share of a rule: its hug threshold, its taper past the scalp's edge, its hem.
// Different rules read it at points shifted apart, so their values are independent.
constexpr float kRootNoiseCell = 0.05f;  // world units (5 mm)
float rootNoise(float x, float y, float z);

}  // namespace hairsketch
