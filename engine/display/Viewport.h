#pragma once
/// @file Viewport.h
/// Where a picture of a given aspect ratio sits in a window: as large as fits, centred, the
/// rest left as margin (letterboxing), so the scene keeps its shape at any window size.

#include <algorithm>
#include <cmath>

namespace modeflow::display {

struct Viewport {
    int x = 0, y = 0;  ///< top-left corner in window pixels
    int width = 0, height = 0;

    /// The largest rectangle of `aspect` (width / height) centred in a windowWidth ×
    /// windowHeight window.
    static Viewport letterbox(int windowWidth, int windowHeight, double aspect) {
        Viewport v;
        v.width = std::max(1, std::min(windowWidth, int(std::lround(windowHeight * aspect))));
        v.height = std::max(1, std::min(windowHeight, int(std::lround(v.width / aspect))));
        v.x = (windowWidth - v.width) / 2;
        v.y = (windowHeight - v.height) / 2;
        return v;
    }

    /// A point given as fractions of the window (x right, y down) in fractions of the viewport
    /// (values outside [0, 1] lie in the margin).
    void toViewport(double windowX, double windowY, int windowWidth, int windowHeight, double& u,
                    double& v) const {
        u = (windowX * windowWidth - x) / width;
        v = (windowY * windowHeight - y) / height;
    }
};

}  // namespace modeflow::display
