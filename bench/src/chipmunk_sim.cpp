// The Chipmunk 7.0.3 adapter (Debian's libchipmunk-dev), written from its documented API.
// Chipmunk is run with its defaults (10 iterations, 0.1 m collision slop, bounding-box tree, no
// sleeping; --chipmunk-sleep turns sleeping on).

#include "sim.hpp"

#include <chipmunk/chipmunk.h>

#include <vector>

namespace bench {
namespace {

cpVect toCp(Vec2 v) { return cpv(v.x, v.y); }

class ChipmunkSim final : public Sim {
public:
    explicit ChipmunkSim(const WorldSpec& spec) : space_(cpSpaceNew()), timeStep_(spec.timeStep) {
        cpSpaceSetGravity(space_, toCp(spec.gravity));
        // Chipmunk's manual: sleeping is off until a sleep time threshold is set; Box2D's 0.5 s when asked.
        if (spec.chipmunkSleep) cpSpaceSetSleepTimeThreshold(space_, 0.5);
    }
    ~ChipmunkSim() override {
        // cpSpaceFree frees neither bodies, shapes nor constraints: remove and free what this adapter made.
        for (cpConstraint* constraint : constraints_) {
            cpSpaceRemoveConstraint(space_, constraint);
            cpConstraintFree(constraint);
        }
        for (cpShape* shape : shapes_) {
            cpSpaceRemoveShape(space_, shape);
            cpShapeFree(shape);
        }
        for (cpBody* body : bodies_) {
            cpSpaceRemoveBody(space_, body);
            cpBodyFree(body);
        }
        cpSpaceFree(space_);
    }
    ChipmunkSim(const ChipmunkSim&) = delete;
    ChipmunkSim& operator=(const ChipmunkSim&) = delete;

    int addBall(const BallSpec& s) override {
        cpBody* body = cpBodyNew(s.mass, cpMomentForCircle(s.mass, 0.0, s.radius, cpvzero));
        cpBodySetPosition(body, toCp(s.position));
        cpBodySetVelocity(body, toCp(s.velocity));
        add(body);
        cpShape* shape = cpCircleShapeNew(body, s.radius, cpvzero);
        // Chipmunk multiplies both shapes' elasticity and friction, as rube does.
        cpShapeSetElasticity(shape, s.bounciness);
        cpShapeSetFriction(shape, s.friction);
        add(shape);
        balls_.push_back(body);
        return static_cast<int>(balls_.size()) - 1;
    }

    void addLine(const LineSpec& s) override {
        cpBody* body = cpSpaceGetStaticBody(space_);
        if (s.velocity.x != 0.0 || s.velocity.y != 0.0) {
            body = cpBodyNewKinematic();
            cpBodySetVelocity(body, toCp(s.velocity));
            add(body);
        }
        cpShape* shape = cpSegmentShapeNew(body, toCp(s.a), toCp(s.b), s.radius);
        cpShapeSetElasticity(shape, s.bounciness);
        cpShapeSetFriction(shape, s.friction);
        add(shape);
    }

    int addBox(const BoxSpec& s) override {
        const double w = 2.0 * s.halfExtents.x, h = 2.0 * s.halfExtents.y;
        const double mass = s.density * w * h;
        cpBody* body = s.fixed ? cpBodyNewStatic() : cpBodyNew(mass, cpMomentForBox(mass, w, h));
        cpBodySetPosition(body, toCp(s.position));
        cpBodySetAngle(body, s.angle);
        add(body);
        cpShape* shape = cpBoxShapeNew(body, w, h, 0.0);
        cpShapeSetElasticity(shape, s.bounciness);
        cpShapeSetFriction(shape, s.friction);
        add(shape);
        boxes_.push_back(body);
        return static_cast<int>(boxes_.size()) - 1;
    }

    void step() override { cpSpaceStep(space_, timeStep_); }
    int ballCount() const override { return static_cast<int>(balls_.size()); }
    BallState ball(int i) const override {
        const cpBody* b = balls_[static_cast<std::size_t>(i)];
        const cpVect p = cpBodyGetPosition(b), v = cpBodyGetVelocity(b);
        return {{p.x, p.y}, {v.x, v.y}, cpBodyGetAngularVelocity(b), cpBodyGetAngle(b)};
    }

    // Chipmunk 7's pivot (a pin), simple motor, gear and damped spring, from its documented API; it
    // has no pulley.
    bool addJoint(const JointSpec& s) override {
        cpBody* a = balls_.at(static_cast<std::size_t>(s.a));
        cpBody* world = cpSpaceGetStaticBody(space_);
        switch (s.kind) {
        case JointSpec::Kind::pin:
            add(cpPivotJointNew(world, a, cpBodyGetPosition(a)));
            if (s.maxTorque > 0.0) {
                // cpSimpleMotor drives wB - wA to -rate: with the ball as a, the ball turns at `rate`.
                cpConstraint* motor = cpSimpleMotorNew(a, world, s.motorSpeed);
                cpConstraintSetMaxForce(motor, s.maxTorque);
                add(motor);
            }
            return true;
        case JointSpec::Kind::gear: {
            // cpGearJoint holds wA = ratio_cp wB; rube's angle_a + ratio angle_b = constant is ratio_cp = -ratio.
            cpBody* b = balls_.at(static_cast<std::size_t>(s.b));
            add(cpGearJointNew(a, b, 0.0, -s.ratio));
            return true;
        }
        case JointSpec::Kind::spring:
            add(cpDampedSpringNew(world, a, toCp(s.anchor), cpvzero, s.restLength, s.stiffness, s.damping));
            return true;
        case JointSpec::Kind::pulley: break;
        }
        lacksJoint_ = true;
        return false;
    }

    int boxCount() const override { return static_cast<int>(boxes_.size()); }
    BoxState box(int i) const override {
        const cpBody* b = boxes_[static_cast<std::size_t>(i)];
        const cpVect p = cpBodyGetPosition(b), v = cpBodyGetVelocity(b);
        return {{p.x, p.y}, cpBodyGetAngle(b), {v.x, v.y}, cpBodyGetAngularVelocity(b)};
    }

private:
    void add(cpBody* body) { bodies_.push_back(cpSpaceAddBody(space_, body)); }
    void add(cpShape* shape) { shapes_.push_back(cpSpaceAddShape(space_, shape)); }
    void add(cpConstraint* constraint) { constraints_.push_back(cpSpaceAddConstraint(space_, constraint)); }

    cpSpace* space_;
    double timeStep_;
    std::vector<cpBody*> balls_;
    std::vector<cpBody*> boxes_;
    std::vector<cpBody*> bodies_;
    std::vector<cpShape*> shapes_;
    std::vector<cpConstraint*> constraints_;
};

[[maybe_unused]] const bool registered = registerEngine(
    {"chipmunk-7.0.3", EngineKind::peer, 11,
     [](const WorldSpec& spec) { return std::make_unique<ChipmunkSim>(spec); }});

} // namespace
} // namespace bench
