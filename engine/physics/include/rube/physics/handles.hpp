#pragma once
/// Handles: how a caller names a body, segment, rope, pivot or joint of a World. A handle is an index into
/// the world's handle table plus a generation: removing the thing bumps its entry's generation, so a
/// handle kept after a remove is detected (World::isValid says false, accessors throw
/// std::invalid_argument) even when a later add reuses the entry (Box2D v3's ids).

#include <cstdint>
#include <functional>

namespace rube {

/// A typed handle: `Tag` keeps a circle's handle from naming a segment. The default is the null handle.
template <class Tag>
struct Handle {
    std::int32_t index = -1;      ///< entry in the world's table of this kind, -1 for the null handle
    std::uint32_t generation = 0; ///< the entry's generation when the handle was made
    /// True for the null handle (never valid in any world).
    bool isNull() const { return index < 0; }
    friend bool operator==(Handle, Handle) = default;
};

struct CircleTag;
struct SegmentTag;
struct BodyTag;
struct RopeTag;
struct PivotTag;
struct JointTag;

using CircleId = Handle<CircleTag>;   ///< a circle of a World
using SegmentId = Handle<SegmentTag>; ///< a segment of a World
using BodyId = Handle<BodyTag>;       ///< a rigid body (box, capsule) of a World
using RopeId = Handle<RopeTag>;       ///< a rope of a World
using PivotId = Handle<PivotTag>;     ///< a pivot of a World
using JointId = Handle<JointTag>;     ///< a joint (revolute, spring, gear, ...) of a World

} // namespace rube

/// Handles are keys of unordered maps and sets too.
template <class Tag>
struct std::hash<rube::Handle<Tag>> {
    std::size_t operator()(rube::Handle<Tag> h) const noexcept {
        return std::hash<std::uint64_t>{}(static_cast<std::uint64_t>(static_cast<std::uint32_t>(h.index)) << 32 |
                                          h.generation);
    }
};
