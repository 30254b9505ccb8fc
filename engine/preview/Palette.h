#pragma once
/// @file Palette.h
/// The colours the previews share, so 2D pictures, 3D renders and contact sheets look like one
/// family: a dark blue-grey background, a lighter slate for walls, white-blue smoke warming
/// towards orange where it is hot, flames yellow-orange. Values are sRGB bytes.

#include "engine/preview/Image.h"

namespace modeflow::preview::palette {

inline constexpr Rgba kBackground{14, 16, 22, 255};
inline constexpr Rgba kWall{64, 70, 86, 255};
inline constexpr Rgba kSmoke{236, 240, 250, 255};
inline constexpr Rgba kHotSmoke{255, 168, 84, 255};
/// Where fuel burns: a bright yellow-orange, lighter than hot smoke, as flames glow.
inline constexpr Rgba kFlame{255, 196, 64, 255};
/// Particles: a leaf green-gold that reads on dark background and white smoke alike.
inline constexpr Rgba kParticle{214, 178, 40, 255};
inline constexpr Rgba kSheetBackground{6, 7, 10, 255};
inline constexpr Rgba kLabel{250, 250, 250, 255};

}  // namespace modeflow::preview::palette
