#pragma once
/// Internal to the scene file parser: the state shared by the readers of each kind of table.

#include "scene.hpp"
#include "toml_reader.hpp"

#include <functional>
#include <map>
#include <string>

namespace rube::game {

/// What the table readers share while one file is read.
struct SceneReading {
    Diagnostics& diag;                                     ///< where every reader reports
    SceneDesc& scene;                                      ///< what the readers fill in
    std::map<std::string, int, std::less<>> pathIndex;     ///< path name -> index in scene.paths
    std::map<std::string, SourcePlace, std::less<>> names; ///< every body and item name -> where it was defined
};

/// Reads every [[circle]] of the file into scene.circles.
void readCircles(TableReader& root, SceneReading& reading);
/// Reads every [[circle_grid]] of the file, appending its circles row by row from the bottom.
void readCircleGrids(TableReader& root, SceneReading& reading);
/// Reads every [[segment]] of the file into scene.segments.
void readSegments(TableReader& root, SceneReading& reading);
/// Reads every [[box]] of the file into scene.bodies (lecture 3's blocks unless fixed_rotation = false).
/// Reads every [[rope]] of the file into scene.ropes (after the circles, which ropes name).
void readRopes(TableReader& root, SceneReading& reading);

/// Reads every [[box]], then every [[capsule]] into scene.bodies, then every [[pivot]] into scene.pivots.
void readRigidBodies(TableReader& root, SceneReading& reading);
/// Reads every [[joint]] into scene.joints (after the bodies, which joints name).
void readJoints(TableReader& root, SceneReading& reading);
/// True when the scene has bodies only the solver moves: turning boxes, capsules, pivots or joints, its
/// own or its parts' (a crate, a domino), or those of a kind its inventory gives.
bool needsRotatingSolver(const SceneDesc& scene);
/// Why `method` cannot move what needsRotatingSolver found, or empty when it can: solver and auto
/// move it all; exact a scene whose only such things are springs to fixed points with a closed
/// form (the world is built and asked, World's requireJointMethod); discrete and turn-based nothing.
/// A refusal for joints alone is requireJointMethod's message; otherwise empty is returned for
/// "cannot" too, and the caller says what its own message says.
bool methodMovesRotating(const SceneDesc& scene, Method method, std::string& why);

/// Reads [[item]], [inventory], [[zone]] and [goal] into scene.level, then checks every reference by name.
void readLevel(TableReader& root, SceneReading& reading);

/// A box written as `min` and `max` corners, max above and to the right of min, or nothing after
/// reporting why; `what` names it in the errors ("bounds", "view", "area").
std::optional<Aabb> readBox(TableReader& box, std::string_view what);

/// Reads an optional `name` key and registers it, reporting an empty or repeated name; "" when absent.
std::string readBodyName(TableReader& table, SceneReading& reading, Need need = Need::optional);

/// The index of the path a body's `path` key names, reporting an unknown name (with the
/// closest defined name) at the key; nothing when the key is absent or wrong.
std::optional<int> readPathReference(TableReader& table, SceneReading& reading);

} // namespace rube::game
