// The bucket: a fixed floor and two walls; a ball-in-bucket goal counts a ball at rest inside it.
#include "part_common.hpp"

namespace rube::game::parts {
namespace {

struct BucketParams {
    double width = 1.2;  // m
    double height = 0.8; // its walls, m
};

constexpr PartKey kKeys[] = {kKindKey,
                             kNameKey,
                             {"position", "required", "[x, y] m: the middle of its floor"},
                             {"width", "1.2", "m"},
                             {"height", "0.8", "its walls, m"}};

class BucketKind final : public PartKind {
public:
    std::string_view name() const override { return "bucket"; }
    int order() const override { return 10; }
    int referenceOrder() const override { return 4; }
    std::string_view summary() const override { return "a fixed floor and two walls, bounciness 0.1; needs a name"; }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool needsName() const override { return true; }
    bool plays(PartRole role) const override { return role == PartRole::aimTarget || role == PartRole::goalBucket; }
    ItemDesc make(Vec2 position) const override { return made(position, BucketParams{}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        BucketParams& p = item.params.as<BucketParams>();
        if (const auto w = table.number("width", kSizeRange)) p.width = *w;
        if (const auto h = table.number("height", kSizeRange)) p.height = *h;
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        // Floor and two walls, the walls standing on the floor's ends.
        const BucketParams& p = item.params.as<BucketParams>();
        const double half = 0.5 * p.width;
        const Vec2 left = item.position + Vec2{-half, 0.0};
        const Vec2 right = item.position + Vec2{half, 0.0};
        const Vec2 up{0.0, p.height};
        const Material material = bouncy(0.1);
        ItemBodies bodies;
        bodies.segments.push_back({left, right, kBoardRadius, material, -1});
        bodies.segments.push_back({left, left + up, kBoardRadius, material, -1});
        bodies.segments.push_back({right, right + up, kBoardRadius, material, -1});
        return bodies;
    }
    Aabb extent(const ItemDesc& item) const override {
        const BucketParams& p = item.params.as<BucketParams>();
        const double half = 0.5 * p.width + kBoardRadius;
        return {item.position + Vec2{-half, -kBoardRadius}, item.position + Vec2{half, p.height + kBoardRadius}};
    }
    // Between its walls and below their tops.
    bool holds(const ItemDesc& item, Vec2 point) const override {
        const BucketParams& p = item.params.as<BucketParams>();
        const Vec2 d = point - item.position;
        return std::abs(d.x) < 0.5 * p.width && d.y > 0.0 && d.y < p.height;
    }
    void draw(const PartDrawing& d) const override {
        // The walls are drawn with the world's segments; a tint inside marks where the goal's ball must rest.
        const ItemDesc& item = itemOf(d);
        const BucketParams& p = item.params.as<BucketParams>();
        const auto& goal = d.run.goal();
        if (!(goal && goal->kind == GoalKind::ballInBucket && goal->item == item.name)) return;
        d.list.box(pt(item.position + Vec2{0.0, 0.5 * p.height}),
                   {static_cast<float>(0.5 * p.width), static_cast<float>(0.5 * p.height)}, 0.0f,
                   {render::Palette::greybox()["goal"].withAlpha(0x60), render::Color::transparent(), 0.0f});
    }
};

} // namespace
RUBE_PART(bucket, BucketKind)
} // namespace rube::game::parts
