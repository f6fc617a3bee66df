#pragma once
/// SceneView: turns a physics World into a DrawList, the only place where the two meet.
/// Bodies, the optional debug overlays (trails, impacts) and the HUD line, through a camera
/// fixed for the whole run.

#include "debug_overlays.hpp"
#include "scene.hpp"

#include "rube/render/camera.hpp"
#include "rube/render/draw_list.hpp"

#include <cstdint>
#include <optional>
#include <string>

namespace rube::game {

/// Draws every uncut rope of `world` as a line from its anchor (with a small pin) or other circle
/// to its ball's centre; drawn before the balls, so the line meets each ball at its rim.
void drawRopes(const World& world, render::DrawList& list);
/// Draws every box (a turned rectangle) and capsule with a line along its own x axis, and every pivot's pin.
void drawRigidBodies(const World& world, render::DrawList& list);
/// Draws the joints behind the bodies: springs as coils, pulleys' ropes and wheels, belts, gear
/// teeth turning with their wheels, pistons' cylinders and rods (joint_drawing.cpp).
void drawJoints(const World& world, render::DrawList& list);
/// Draws the joints' marks in front of the bodies: a hinge's pin, a weld's cross.
void drawJointPins(const World& world, render::DrawList& list);

/// Draws chevrons along every conveyor (a segment with a surface speed), pointing the way its
/// surface runs and travelling at that speed with the world's time, so a still belt and a running one differ.
void drawConveyors(const World& world, render::DrawList& list);
/// Draws the air's push on every dynamic ball of a world with air drag: streaks behind it along -v, 0.6 m
/// long per g of drag deceleration (so a ball at its terminal speed trails 0.6 m); nothing without air drag.
void drawAirDrag(const World& world, render::DrawList& list);
/// Draws every pool of water as a translucent band, its top edge the surface; drawn in front of what floats in it.
void drawWaters(const World& world, render::DrawList& list);

/// What a view draws besides the bodies; a caller changes only what it needs.
struct ViewOptions {
    bool trails = false;         ///< --trails: each dynamic circle's recent path (the lecture's debug key D)
    bool impacts = false;        ///< --debug-impacts: points of impact and collision normals
    double trailSeconds = 2.0;   ///< how much of the past a trail shows, in simulated seconds
    double impactSeconds = 0.25; ///< how long an impact marker stays on screen, fading
};

/// Draws one scene's world, frame after frame. Call afterStep() after every World::step(), even
/// for steps that are not drawn, so the trails and impact markers miss nothing in between.
class SceneView {
public:
    /// A view of `world` (in its initial state) named `sceneName` in the HUD, drawn through
    /// `camera` into frames of `frame` pixels.
    SceneView(std::string sceneName, const World& world, render::Camera camera, render::FrameSize frame,
              const ViewOptions& options = {});

    /// Records what the overlays need from the step just taken.
    void afterStep(const World& world);
    /// Clears `list` and fills it with the world as it is now.
    void draw(const World& world, render::DrawList& list) const;

    /// The camera every frame is drawn through.
    const render::Camera& camera() const { return camera_; }
    /// The size of the frames, in pixels.
    render::FrameSize frameSize() const { return frame_; }
    /// The HUD line: scene, steps taken, simulated time, method.
    std::string hudLine(const World& world) const;

private:
    void drawSegments(const World& world, render::DrawList& list) const;
    void drawCircles(const World& world, render::DrawList& list) const;
    void drawHud(const std::string& line, render::DrawList& list) const;

    std::string sceneName_;
    render::Camera camera_;
    render::FrameSize frame_;
    ViewOptions options_;
    std::optional<Trails> trails_;
    std::optional<RecentImpacts> impacts_;
};

} // namespace rube::game
