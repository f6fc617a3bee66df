// The Box2D 2.4.1 adapter (Debian's libbox2d-dev), written from its documented API. Box2D is
// run as its manual recommends: 8 velocity and 3 position iterations, sleeping allowed.

#include "sim.hpp"

#include <box2d/box2d.h>

#include <algorithm>
#include <numbers>
#include <vector>

namespace bench {
namespace {

constexpr int kVelocityIterations = 8;
constexpr int kPositionIterations = 3;

// Box2D mixes restitution with max(a, b); rube and Chipmunk multiply. PreSolve may override a
// contact's restitution, so the pair's C is the same product on every engine.
class ProductRestitution final : public b2ContactListener {
public:
    void PreSolve(b2Contact* contact, const b2Manifold*) override {
        contact->SetRestitution(contact->GetFixtureA()->GetRestitution() * contact->GetFixtureB()->GetRestitution());
    }
};

b2Vec2 toB2(Vec2 v) { return {static_cast<float>(v.x), static_cast<float>(v.y)}; }

class Box2dSim final : public Sim {
public:
    explicit Box2dSim(const WorldSpec& spec)
        : world_(toB2(spec.gravity)), timeStep_(static_cast<float>(spec.timeStep)) {
        world_.SetContactListener(&listener_);
    }

    int addBall(const BallSpec& s) override {
        b2BodyDef bodyDef;
        bodyDef.type = b2_dynamicBody;
        bodyDef.position = toB2(s.position);
        bodyDef.linearVelocity = toB2(s.velocity);
        bodyDef.bullet = s.fast;
        b2Body* body = world_.CreateBody(&bodyDef);
        b2CircleShape circle;
        circle.m_radius = static_cast<float>(s.radius);
        b2FixtureDef fixture;
        fixture.shape = &circle;
        // Density from the mass, so a ball weighs what the scene says: rho = m / (pi r^2).
        fixture.density = static_cast<float>(s.mass / (std::numbers::pi * s.radius * s.radius));
        fixture.restitution = static_cast<float>(s.bounciness);
        fixture.friction = static_cast<float>(s.friction);
        body->CreateFixture(&fixture);
        balls_.push_back(body);
        return static_cast<int>(balls_.size()) - 1;
    }

    void addLine(const LineSpec& s) override {
        b2BodyDef bodyDef;
        const bool moving = s.velocity.x != 0.0 || s.velocity.y != 0.0;
        bodyDef.type = moving ? b2_kinematicBody : b2_staticBody;
        bodyDef.linearVelocity = toB2(s.velocity);
        b2Body* body = world_.CreateBody(&bodyDef);
        // An edge carries Box2D's fixed skin (b2_polygonRadius); the line's own radius has no edge
        // equivalent, so lines in the bench scenes are thin (radius 0).
        b2EdgeShape edge;
        edge.SetTwoSided(toB2(s.a), toB2(s.b));
        b2FixtureDef fixture;
        fixture.shape = &edge;
        fixture.restitution = static_cast<float>(s.bounciness);
        fixture.friction = static_cast<float>(s.friction);
        body->CreateFixture(&fixture);
    }

    int addBox(const BoxSpec& s) override {
        b2BodyDef bodyDef;
        bodyDef.type = s.fixed ? b2_staticBody : b2_dynamicBody;
        bodyDef.position = toB2(s.position);
        bodyDef.angle = static_cast<float>(s.angle);
        b2Body* body = world_.CreateBody(&bodyDef);
        b2PolygonShape shape;
        shape.SetAsBox(static_cast<float>(s.halfExtents.x), static_cast<float>(s.halfExtents.y));
        b2FixtureDef fixture;
        fixture.shape = &shape;
        fixture.density = static_cast<float>(s.density);
        fixture.restitution = static_cast<float>(s.bounciness);
        fixture.friction = static_cast<float>(s.friction);
        body->CreateFixture(&fixture);
        boxes_.push_back(body);
        return static_cast<int>(boxes_.size()) - 1;
    }

    void step() override { world_.Step(timeStep_, kVelocityIterations, kPositionIterations); }
    int ballCount() const override { return static_cast<int>(balls_.size()); }
    BallState ball(int i) const override {
        const b2Body* b = balls_[static_cast<std::size_t>(i)];
        return {{b->GetPosition().x, b->GetPosition().y},
                {b->GetLinearVelocity().x, b->GetLinearVelocity().y},
                b->GetAngularVelocity(),
                b->GetAngle()};
    }

    // Box2D 2.4.1's revolute (with its motor), gear, pulley and distance joint (a spring when given
    // stiffness and damping), from its documented API.
    bool addJoint(const JointSpec& s) override {
        b2Body* a = balls_.at(static_cast<std::size_t>(s.a));
        switch (s.kind) {
        case JointSpec::Kind::pin: {
            b2RevoluteJointDef d;
            d.Initialize(ground(), a, a->GetPosition());
            d.enableMotor = s.maxTorque > 0.0;
            d.motorSpeed = static_cast<float>(s.motorSpeed);
            d.maxMotorTorque = static_cast<float>(s.maxTorque);
            pins_.resize(std::max(pins_.size(), static_cast<std::size_t>(s.a) + 1), nullptr);
            pins_[static_cast<std::size_t>(s.a)] = world_.CreateJoint(&d);
            return true;
        }
        case JointSpec::Kind::gear: {
            // Box2D's gear: coordinateA + ratio coordinateB = constant, as rube's.
            b2GearJointDef d;
            d.joint1 = pins_.at(static_cast<std::size_t>(s.a));
            d.joint2 = pins_.at(static_cast<std::size_t>(s.b));
            d.bodyA = d.joint1->GetBodyB();
            d.bodyB = d.joint2->GetBodyB();
            d.ratio = static_cast<float>(s.ratio);
            world_.CreateJoint(&d);
            return true;
        }
        case JointSpec::Kind::pulley: {
            b2Body* b = balls_.at(static_cast<std::size_t>(s.b));
            b2PulleyJointDef d;
            d.Initialize(a, b, toB2(s.groundA), toB2(s.groundB), a->GetPosition(), b->GetPosition(),
                         static_cast<float>(s.ratio));
            world_.CreateJoint(&d);
            return true;
        }
        case JointSpec::Kind::spring: {
            b2DistanceJointDef d;
            d.Initialize(ground(), a, toB2(s.anchor), a->GetPosition());
            d.length = static_cast<float>(s.restLength);
            d.minLength = 0.0f;
            d.maxLength = 1e6f;
            d.stiffness = static_cast<float>(s.stiffness);
            d.damping = static_cast<float>(s.damping);
            world_.CreateJoint(&d);
            return true;
        }
        }
        return false;
    }

    int boxCount() const override { return static_cast<int>(boxes_.size()); }
    BoxState box(int i) const override {
        const b2Body* b = boxes_[static_cast<std::size_t>(i)];
        return {{b->GetPosition().x, b->GetPosition().y},
                b->GetAngle(),
                {b->GetLinearVelocity().x, b->GetLinearVelocity().y},
                b->GetAngularVelocity()};
    }

private:
    b2Body* ground() {
        if (!ground_) {
            b2BodyDef d;
            ground_ = world_.CreateBody(&d);
        }
        return ground_;
    }

    ProductRestitution listener_;
    b2World world_;
    float timeStep_;
    std::vector<b2Body*> balls_;
    b2Body* ground_ = nullptr;
    std::vector<b2Joint*> pins_; // per ball: its revolute, for the gears
    std::vector<b2Body*> boxes_;
};

[[maybe_unused]] const bool registered = registerEngine(
    {"box2d-2.4.1", EngineKind::peer, 10, [](const WorldSpec& spec) { return std::make_unique<Box2dSim>(spec); }});

} // namespace
} // namespace bench
