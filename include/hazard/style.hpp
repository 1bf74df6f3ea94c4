#pragma once
// Rendering hints for pMarineViewer: colour and marker-shape words (docs/configuration.md,
// docs/messages.md).
// Colours: the X11/CSS named colours (case-insensitive, underscores ignored, so `light_blue`
// equals `lightblue`), `grayN`/`greyN` for N in 0..100, `black`, `invisible`, `empty`,
// `hex:RR,GG,BB`, or three fractions in [0, 1] separated by one of , : % $ #.
// Posted specs repeat the colour text exactly as configured.

#include <string_view>

namespace hazard {

/// True if pMarineViewer understands `text` as a colour (see the file comment).
bool is_known_color(std::string_view text);

/// Marker shapes the original supports (exact lowercase words): circle, square, diamond,
/// triangle, efield, gateway.
bool is_known_shape(std::string_view text);

}  // namespace hazard
