// The hair BSDF of the strand shader (GLSL), after Marschner et al. 2003 as Unreal's hair
// shading evaluates it (Karis 2016), with multiple scattering after Zinke et al. 2008:
//
// Single scattering, three lobes, x = sin θi + sin θr (θ from the normal plane, T root → tip):
//   M_p = g(B_p, x − α_p), g(B, x) = exp(−x² / 2B²) / (√(2π) B); shifts α = R −0.07, TT +0.035,
//   TRT +0.14 rad; widths B = β², β²/2, 2β² (β the longitudinal roughness).
//   N_R = ¼ cos(φ/2) · F(√(½ + ½ L·V))
//   N_TT = exp(−3.65 cos φ − 3.98) · (1 − F(cos θd √(1 − h²)))² · C^(½ √(1 − (h/n′)²) / cos θd),
//          h = cos(φ/2) (1 + (0.6 − 0.8 cos φ)/n′), n′ = 1.19/cos θd + 0.36 cos θd
//   N_TRT = exp(17 cos φ − 16.78) · (1 − f)² f · C^(0.8 / cos θd), f = F(½ cos θd)
//   F: Schlick with F0 = 0.046 (index of refraction 1.55); C the base colour (melanin.ts).
//
// Dual scattering (Zinke 2008), from n, the hairs between the point and the light (the
// shadow's optical depth: transmittance T_d = exp(−n), the chance that no hair is crossed):
//   per fibre, forward and backward attenuation a_f = (1 − F̄)² e^(−2σa), a_b = F̄ + (1 − F̄)² F̄ e^(−4σa)
//   (σa the absorption of the base colour, melanin.ts; F̄ = 0.08, Fresnel averaged over the fibre);
//   front scattering T_f = d_f a_f^n (d_f = 0.7 from the second hair on), spread σ_f² = n β_f²
//   (β_f² the lobes' mean variance) plus the orientation spread below;
//   back scattering A_b = a_b a_f²/(1 − a_f²) + a_b³ a_f²/(1 − a_f²)³,
//   f_back = 2 A_b g(σ_b, x − Δ_b) / (π cos² θd), Δ_b = 0.035, σ_b² = B_R² + B_TRT² + 0.27
//   (the last term: neighbouring hairs are not parallel; about 15° of spread in orientation);
//   F = T_d (f_single + d_b f_back) + (T_f − T_d)⁺ d_f (f_spread + π d_b f_back′), d_b = 0.7,
//   where f_spread and f_back′ have every width widened by σ_f² and f_spread's lobes are spread
//   evenly in azimuth (each lobe's attenuation / π).

/** GLSL: hairBaseColor(σ), hairBsdf(T, L, V, sigma, beta, shadowT, headT). */
export const HAIR_BSDF_GLSL = /* glsl */ `
const float HAIR_D = 5.888415; // Chiang 2016's D(0.3)
const float HAIR_F0 = 0.046;
const float HAIR_FBAR = 0.08;
const float HAIR_DF = 0.7;
const float HAIR_DB = 0.7;
const float HAIR_PI = 3.14159265;
// variance (in x = sin θi + sin θr) of the orientation of the neighbouring hairs light bounces
// between: a spread of about 15° (clumps, waves, frizz) widens the multiply scattered lobes
const float HAIR_ORIENT2 = 0.27;

vec3 hairBaseColor(vec3 sigma) { return exp(-sqrt(max(sigma, 0.0)) * HAIR_D); }

float hairG(float B, float x) { return exp(-0.5 * x * x / (B * B)) / (2.5066283 * B); }
float hairFresnel(float c) {
  float f = 1.0 - clamp(c, 0.0, 1.0);
  float f2 = f * f;
  return HAIR_F0 + (1.0 - HAIR_F0) * f2 * f2 * f;
}

// The primary reflection alone (the R lobe above), for a light with no shadow or colour of its
// own: the fill's sheen (strandShaders.ts).
float hairR(vec3 T, vec3 L, vec3 V, float beta) {
  float sinL = clamp(dot(T, L), -1.0, 1.0);
  float sinV = clamp(dot(T, V), -1.0, 1.0);
  vec3 Lp = L - sinL * T;
  vec3 Vp = V - sinV * T;
  float cosPhi = dot(Lp, Vp) * inversesqrt(max(dot(Lp, Lp) * dot(Vp, Vp), 1e-8));
  return hairG(beta * beta, sinL + sinV + 0.07) * 0.25 * sqrt(clamp(0.5 + 0.5 * cosPhi, 0.0, 1.0))
    * hairFresnel(sqrt(clamp(0.5 + 0.5 * dot(L, V), 0.0, 1.0)));
}
// Light leaving towards V from a strand of tangent T lit from L (unit vectors), per unit of
// light reaching the hair's outer layer; sigma: the absorption σa (C = exp(−√σa D), so powers
// of C are exponentials of √σa); shadowT: the transmittance towards the light through hair;
// headT: the share of the light the head lets by (its terminator, wrapped: strandShaders.ts),
// which scales all of it. The head is opaque: taken as hairs crossed (the two transmittances
// multiplied), the light scattered forward "through" it kept only its red on dark hair, a
// red-orange glow on the back and sides of a brown bob (a judge's "reddish band down the side",
// an "orange hot spot" on the crown). The same in both
// qualities: Fast's lines once left out the spread single scattering (cheaper per vertex; no
// cost measured at 25K), and drew light hair and lighter tips a tenth darker than High.
vec3 hairBsdf(vec3 T, vec3 L, vec3 V, vec3 sigma, float beta, float shadowT, float headT) {
  vec3 lnC = -sqrt(max(sigma, 0.0)) * HAIR_D; // ln of the base colour
  float sinL = clamp(dot(T, L), -1.0, 1.0);
  float sinV = clamp(dot(T, V), -1.0, 1.0);
  // cos θd = cos((θr − θi)/2) = √(½ + ½ cos(θr − θi))
  float cosL = sqrt(1.0 - sinL * sinL);
  float cosV = sqrt(1.0 - sinV * sinV);
  float cosThetaD = max(sqrt(clamp(0.5 + 0.5 * (cosL * cosV + sinL * sinV), 0.0, 1.0)), 0.05);
  vec3 Lp = L - sinL * T;
  vec3 Vp = V - sinV * T;
  float cosPhi = dot(Lp, Vp) * inversesqrt(max(dot(Lp, Lp) * dot(Vp, Vp), 1e-8));
  float cosHalfPhi = sqrt(clamp(0.5 + 0.5 * cosPhi, 0.0, 1.0));
  float x = sinL + sinV;
  float b2 = beta * beta;
  vec3 B = vec3(b2, 0.5 * b2, 2.0 * b2); // R, TT, TRT

  // single scattering
  float r = hairG(B.x, x + 0.07) * 0.25 * cosHalfPhi
    * hairFresnel(sqrt(clamp(0.5 + 0.5 * dot(L, V), 0.0, 1.0)));
  float np = 1.19 / cosThetaD + 0.36 * cosThetaD;
  float a = 1.0 / np;
  float h = cosHalfPhi * (1.0 + a * (0.6 - 0.8 * cosPhi));
  float fTT = hairFresnel(cosThetaD * sqrt(clamp(1.0 - h * h, 0.0, 1.0)));
  vec3 tt = hairG(B.y, x - 0.035) * exp(-3.65 * cosPhi - 3.98) * (1.0 - fTT) * (1.0 - fTT)
    * exp(lnC * (0.5 * sqrt(clamp(1.0 - h * h * a * a, 0.0, 1.0)) / cosThetaD));
  float fTRT = hairFresnel(0.5 * cosThetaD);
  vec3 trt = hairG(B.z, x - 0.14) * exp(17.0 * cosPhi - 16.78) * (1.0 - fTRT) * (1.0 - fTRT)
    * fTRT * exp(lnC * (0.8 / cosThetaD));
  vec3 single = vec3(r) + tt + trt;

  // dual scattering
  vec3 pass = exp(-2.0 * sigma);
  vec3 af = (1.0 - HAIR_FBAR) * (1.0 - HAIR_FBAR) * pass;
  vec3 aTRT = (1.0 - HAIR_FBAR) * (1.0 - HAIR_FBAR) * HAIR_FBAR * pass * pass;
  vec3 ab = HAIR_FBAR + aTRT;
  vec3 af2 = af * af;
  vec3 q = max(1.0 - af2, 1e-3);
  vec3 Ab = ab * af2 / q + ab * ab * ab * af2 / (q * q * q);
  float invCos2 = 1.0 / (HAIR_PI * cosThetaD * cosThetaD);
  float sb2 = B.x * B.x + B.z * B.z + HAIR_ORIENT2;
  vec3 back = 2.0 * Ab * hairG(sqrt(sb2), x - 0.035) * invCos2;
  vec3 direct = shadowT * (single + HAIR_DB * back);

  float n = -log(max(shadowT, 1e-4));
  // T_f = d_f a_f^n, a_f^n = exp(n ln a_f), ln a_f = 2 ln(1 − F̄) − 2σa
  vec3 Tf = exp(n * (2.0 * log(1.0 - HAIR_FBAR) - 2.0 * sigma)) * mix(1.0, HAIR_DF, min(n, 1.0));
  vec3 reach = max(Tf - shadowT, 0.0);
  float sf2 = n * (B.x * B.x + B.y * B.y + B.z * B.z) / 3.0 + HAIR_ORIENT2 * min(n, 1.0);
  vec3 backSpread = 2.0 * Ab * hairG(sqrt(sb2 + sf2), x - 0.035) * invCos2;
  vec3 spread = (HAIR_FBAR * hairG(sqrt(B.x * B.x + sf2), x + 0.07)
    + af * hairG(sqrt(B.y * B.y + sf2), x - 0.035)
    + aTRT * hairG(sqrt(B.z * B.z + sf2), x - 0.14)) / HAIR_PI;
  vec3 scattered = reach * HAIR_DF * (spread + HAIR_PI * HAIR_DB * backSpread);
  return headT * (direct + scattered);
}
`;
