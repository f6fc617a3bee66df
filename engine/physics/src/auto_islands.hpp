#pragma once
// Internal: the islands `auto` chooses a method for. Two bodies are in one island when they could
// meet within the step: their reach boxes overlap (the box of the parabola p + v t + g t^2 / 2 over
// the step, fattened by the body's size, by |v| dt for what an impact within its island may add to
// its speed, and by the resting slop exact settles contacts within), or a rope joins them, or the
// solver put them to sleep together. Static and kinematic segments and non-dynamic circles are
// infinite masses shared by every island: two balls resting on one floor do not affect each other.
// Rigid bodies, fixed ones too, are nodes of their own, since exact cannot model every shape.
// Neighbourhoods are looser: reach boxes fattened once more by the body's own size. A crowd about
// to form (a pile falling in rows a few centimetres apart) is one neighbourhood before its islands
// touch, so auto can judge what exact would cost it before it pays for it.

#include "broadphase_grid.hpp"
#include "step_method.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace rube {

/// One island, with what auto needs to choose its method.
struct Island {
    int first = 0;         ///< its first node in AutoIslands::members(), which lists each island's nodes in index order
    int count = 0;         ///< how many nodes
    int dynamicBodies = 0; ///< dynamic circles and dynamic rigid bodies in it
    bool needsSolver =
        false;             ///< friction can act in it, or it holds a turning body, a pivot or a moving non-block body
    int neighbourhood = 0; ///< islands with equal values are within a body's size of each other (a crowd forming)
};

/// Groups the step's bodies into islands. Nodes: dynamic circle i is node i, rigid body b is node
/// circles.size() + b; a non-dynamic circle is no node (islandOf gives -1).
class AutoIslands {
public:
    /// Builds the islands of this step, ordered by their lowest node index (deterministic).
    void build(const StepContext& ctx, double dt);

    /// The islands, by lowest node index.
    std::span<const Island> islands() const { return islands_; }
    /// The nodes of `island`, in index order.
    std::span<const int> members(const Island& island) const {
        return std::span<const int>(members_).subspan(static_cast<std::size_t>(island.first),
                                                      static_cast<std::size_t>(island.count));
    }
    /// The island of `node`, or -1 for a non-dynamic circle.
    int islandOf(int node) const { return islandOf_[static_cast<std::size_t>(node)]; }

private:
    static int find(std::vector<int>& parent, int node);
    static void join(std::vector<int>& parent, int a, int b);

    std::vector<int> parent_;        // union-find over islands, the root is the lowest index
    std::vector<int> looseParent_;   // union-find over neighbourhoods
    std::vector<double> sizes_;      // per node: its radius (a circle) or bounding radius (a rigid body)
    std::vector<BoundingBox> boxes_; // per node: its reach box (unused for non-dynamic circles)
    std::vector<std::uint8_t> isNode_;
    std::vector<std::uint8_t> friction_;  // per node: a dynamic circle with friction
    std::vector<std::uint8_t> needs_;     // per node: needs the solver by itself
    std::vector<double> springReach_;     // per circle: how far its exact spring may carry it this step, or -1
    std::vector<int> order_;              // the nodes, in index order (the grid's items)
    std::vector<BoundingBox> looseBoxes_; // per grid item: its neighbourhood box
    std::vector<std::uint8_t> looks_;     // per grid item: it looks for pairs (asleep circles do not)
    std::vector<CandidatePair> pairs_;
    BroadphaseGrid grid_;
    std::vector<BoundingBox> frictionShared_; // swept boxes of shared shapes with friction
    std::vector<int> frictionCircles_;        // per island: dynamic circles with friction
    std::vector<std::uint8_t> nonBlocks_;     // per island: holds a body exact does not model
    std::vector<Island> islands_;
    std::vector<int> members_;
    std::vector<int> islandOf_;
};

} // namespace rube
