// The lower hairline round the back of the head (the nape's and behind the ears'), where a short
// cut fades out: with the shape rules, short hair (hair_fall.hpp kHugLength) that comes down to
// it ends anywhere in a band round it (kFadeAbove to kFadeBelow, each strand's own share seeded
// where its root is), never shorter than kFadeShortest, so a pixie's or a crop's nape and sides
// thin out to the skin as a tapered cut does instead of ending together on one blunt line (fresh
// eyes round 16).
#pragma once

#include <vector>

namespace hairsketch {

// The band (world units) round the lower hairline over which short hair ends: from 2.5 cm above
// it to 1 cm below it, never before the strand has 6 mm.
constexpr float kFadeAbove = 0.25f, kFadeBelow = 0.1f, kFadeShortest = 0.06f;
// The line is kept per bin of the angle about the head's vertical axis (0: straight back), over
// the head behind kNapeFront (world units in front of the centre: the ears are behind it) and
// below kNapeTop above its centre (the scalp's edge over the ears is part of it).
constexpr int kNapeBins = 48;
constexpr float kNapeFront = 0.1f, kNapeTop = 0.25f;
// Only a step heading down by at least this share of its length ends there: hair combed back
// over the ears (a slicked back's sides) passes above them.
constexpr float kFadeDown = 0.5f;

// The lowest height of the scalp's edges (soft_hairline.hpp scalpEdges: 6 floats each) per bin
// (NaN where no edge passes), behind kNapeFront and below the centre.
std::vector<float> napeLine(const std::vector<float>& edges, const float centre[3]);

// The line's highest point (-infinity when it has none).
float napeLineTop(const std::vector<float>& line);

// The line's height at (x, z) (linear between bins), NaN in front of kNapeFront, where the line
// has no edge, or when line is empty.
float napeLineAt(const std::vector<float>& line, const float centre[3], float x, float z);

}  // namespace hairsketch
