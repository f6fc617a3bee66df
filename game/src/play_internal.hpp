#pragma once
/// Internal to the play session's files (play_*.cpp) and the editor's (edit_*.cpp): the camera,
/// snapping, angle spelling and trail sizes they share.

#include "scene.hpp"
#include "script_file.hpp"

#include "rube/render/camera.hpp"

#include <cmath>
#include <cstddef>
#include <string>

namespace rube::game::play {

inline constexpr double kAimStepsPerDegree = 2.0; ///< aims by mouse or wheel snap to half degrees
inline constexpr double kTrailSeconds = 2.0;      ///< how long the motion trails (D, C) remember
inline constexpr std::size_t kTrailPoints = 512;  ///< and how many points each keeps

/// To the nearest 1/perUnit: dividing the whole count gives the double nearest k / perUnit, which
/// prints as the short decimal a person would write (0.3, not 0.30000000000000004).
inline double snap(double value, double perUnit) { return std::round(value * perUnit) / perUnit; }

/// Into (-180, 180]: an angle keeps one spelling however often it is turned.
inline double normalDegrees(double degrees) {
    while (degrees > 180.0) degrees -= 360.0;
    while (degrees <= -180.0) degrees += 360.0;
    return degrees;
}

/// The camera a level is drawn through: its [view], else what frames it (as `rube run` draws it).
render::Camera levelCamera(const SceneDesc& level, render::FrameSize frame);

/// Messages spell numbers as scripts do, so the bar says what a recording will hold.
inline std::string number(double value) { return scriptNumber(value); }

} // namespace rube::game::play
