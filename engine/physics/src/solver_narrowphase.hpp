#pragma once
// Internal: the circle solver's narrowphase and its contacts between steps: remembering how each
// pair ended the last step, building this step's contacts from candidate pairs (narrowphase),
// ordering them for the Gauss-Seidel sweeps (solver_soft_step.hpp), and reporting impacts.

#include "broadphase_grid.hpp"
#include "solver_soft_step.hpp"
#include "step_method.hpp"
#include "world_handles.hpp"

#include <span>
#include <vector>

namespace rube {

/// How a pair ended the last step: its normal and accumulated impulses.
struct PreviousContact {
    Vec2 normal;                 ///< from the other body towards the circle
    double impulse = 0.0;        ///< accumulated normal impulse of the last substep
    double tangentImpulse = 0.0; ///< accumulated friction impulse of the last substep (0 without friction)
};

/// Last step's contacts by pair, so a resting pile starts each step already pushing (warm starting)
/// and a pair that was touching keeps its side.
class ContactCache {
public:
    /// The pair's state at the end of the last step, or null for a new pair (and for every pair once
    /// bodies were added, since indices then mean other bodies).
    const PreviousContact* find(int circle, int other, int circleCount, int segmentCount) const;
    /// Remembers the contacts, grouped by circle (a counting sort) for lookup next step, with their
    /// friction impulses when `tangentImpulses` is parallel to them (empty: a step without friction).
    void store(std::span<const ContactConstraint> contacts, std::span<const double> tangentImpulses, int circleCount,
               int segmentCount);
    /// As store with no contacts (a step of a world entirely asleep), without a pass over the circles
    /// when it already holds none for these counts.
    void storeNone(int circleCount, int segmentCount);
    /// Moves the stored pairs to the bodies' new slots, dropping those of bodies that left.
    void remap(const SlotRemap& remap);

private:
    std::vector<int> ownerStart_; // per circle: its first stored pair; size circles + 1
    std::vector<int> cursor_;     // scratch for the counting sort
    std::vector<int> other_;
    std::vector<PreviousContact> previous_;
    int circleCount_ = -1;
    int segmentCount_ = -1;
};

/// Builds this step's contacts from candidate pairs with the normal and gap at the start of the step,
/// keeping a pair only when its gap is within the two speculative margins (margins: circles first,
/// then segments, as solver bodies), and warm starts each from the cache.
void buildContacts(std::span<const CandidatePair> pairs, std::span<const Circle> circles,
                   std::span<const Segment> segments, std::span<const double> margins,
                   std::span<const double> inverseMass, const ContactCache& cache,
                   std::vector<ContactConstraint>& contacts, std::vector<ContactRecord>& records);

/// Buffers orderContacts keeps between steps.
struct ContactOrderScratch {
    std::vector<int> rank, key, start, perCircle; ///< counting-sort keys and counters
    std::vector<ContactConstraint> contacts;      ///< the reordered contacts before swapping in
    std::vector<ContactRecord> records;           ///< the reordered records before swapping in
};

/// Orders contacts (records alike) for the Gauss-Seidel sweeps: contacts between dynamic circles in
/// layers `layerHeight` thick from the top down, so weight reaches the bottom within one sweep;
/// then contacts with infinite-mass bodies, so the floor has the last word and a crushed pile cannot
/// push a ball through it. Within a layer every circle's first contact comes before any circle's
/// second, so consecutive contacts rarely share a body and the CPU overlaps their work; and among
/// those, the contacts warm started pushing before the others, so the sweeps' branches run in two
/// long predictable stretches instead of a pattern too long for the CPU to learn.
void orderContacts(std::vector<ContactConstraint>& contacts, std::vector<ContactRecord>& records,
                   std::span<const Vec2> positions, std::span<const double> inverseMass, Vec2 up, double layerHeight,
                   ContactOrderScratch& scratch);

/// Appends an Impact for every contact that first touched faster than ctx.restingSpeed and counts
/// the slower touches as resting contacts; returns the number of impacts. Circles hold the step's end
/// positions (the contact point is on the circle's surface there).
int recordContactImpacts(std::span<const ContactConstraint> contacts, std::span<const ContactRecord> records,
                         std::span<const Circle> circles, StepContext& ctx);

} // namespace rube
