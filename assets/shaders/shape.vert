#version 330 core
// Every shape is one instanced quad in pixel space (origin bottom-left, y up), grown by one
// pixel around the shape so that its antialiased edge fits. Whatever is the same for every
// pixel of a shape is worked out here, once per corner, and handed on flat: llvmpipe shades
// pixels in SIMD and runs both sides of a branch, so per-pixel work must be small and uniform.

layout(location = 0) in vec4 geomA;         // kind-specific geometry, pixels (see shape_instance.hpp)
layout(location = 1) in vec4 geomB;
layout(location = 2) in float outlineWidth;  // pixels, drawn inside the edge
layout(location = 3) in uint kindAndFlags;   // low byte: kind; bits 8 and up: per-kind flags
layout(location = 4) in vec4 fillColour;     // straight alpha
layout(location = 5) in vec4 outlineColour;

uniform vec2 frameSize;  // pixels

// Rounded boxes (discs, capsules, boxes): A = (centre, axis), B = (half extents, corner
// radius, outline width), C and D = the planes (normal, offset) that clip a chained stroke at
// its start and end joints. Triangles: A, B, C = the planes of the three edges, .w = edge mode.
flat out vec4 vShapeA;
flat out vec4 vShapeB;
flat out vec4 vShapeC;
flat out vec4 vShapeD;
flat out uint vIsTriangle;
flat out vec4 vFill;
flat out vec4 vOutline;

const uint kindDisc = 0u;
const uint kindCapsule = 1u;
const uint kindBox = 2u;
const uint kindTriangle = 3u;

// Coverage falls to zero half a pixel outside an edge; one pixel of margin leaves room to spare.
const float margin = 1.0;

// Planes that keep every pixel: dot(0, p) - (-1) >= 0 and dot(0, p) - 1 < 0.
const vec4 keepAllStart = vec4(0.0, 0.0, -1.0, 0.0);
const vec4 keepAllEnd = vec4(0.0, 0.0, 1.0, 0.0);

// The plane through a chain's joint with its normal at `angle`. The two strokes meeting at a
// joint pass the same origin and angle and so get the very same plane, bit for bit.
vec4 jointPlane(vec2 origin, float angle) {
    vec2 n = vec2(cos(angle), sin(angle));
    return vec4(n, dot(n, origin), 0.0);
}

// Edge a-b of the triangle whose third vertex is w. A polygon's boundary edge gets an outward
// unit normal (mode 0) and is antialiased. An edge shared with a neighbouring triangle is
// written in a canonical order so both triangles get the identical plane; mode +1 or -1 says
// which side is this triangle's, and exactly one of the two owns a pixel on the line.
vec4 edgePlane(vec2 a, vec2 b, vec2 w, bool boundary) {
    if (boundary) {
        vec2 e = b - a;
        vec2 n = normalize(vec2(e.y, -e.x));
        if (dot(n, w - a) > 0.0) n = -n;
        return vec4(n, dot(n, a), 0.0);
    }
    bool swapEnds = a.x > b.x || (a.x == b.x && a.y > b.y);
    vec2 lo = swapEnds ? b : a;
    vec2 hi = swapEnds ? a : b;
    vec2 n = vec2(lo.y - hi.y, hi.x - lo.x);
    float c = dot(n, lo);
    return vec4(n, c, dot(n, w) - c > 0.0 ? 1.0 : -1.0);
}

void main() {
    // Triangle strip order: (-1,-1), (1,-1), (-1,1), (1,1).
    vec2 corner = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1)) * 2.0 - 1.0;
    uint kind = kindAndFlags & 255u;
    vec2 p;
    vShapeC = keepAllStart;
    vShapeD = keepAllEnd;
    vIsTriangle = kind == kindTriangle ? 1u : 0u;
    if (kind == kindTriangle) {
        vec2 v0 = geomA.xy;
        vec2 v1 = geomA.zw;
        vec2 v2 = geomB.xy;
        vShapeA = edgePlane(v0, v1, v2, ((kindAndFlags >> 8u) & 1u) == 1u);
        vShapeB = edgePlane(v1, v2, v0, ((kindAndFlags >> 9u) & 1u) == 1u);
        vShapeC = edgePlane(v2, v0, v1, ((kindAndFlags >> 10u) & 1u) == 1u);
        vec2 lo = min(min(v0, v1), v2) - margin;
        vec2 hi = max(max(v0, v1), v2) + margin;
        p = mix(lo, hi, corner * 0.5 + 0.5);
    } else {
        vec2 centre;
        vec2 axis = vec2(1.0, 0.0);
        vec2 halfExtents;
        float cornerRadius;
        if (kind == kindDisc) {
            // A disc is a square box rounded by its whole half width.
            centre = geomA.xy;
            halfExtents = vec2(geomA.z);
            cornerRadius = geomA.z;
        } else if (kind == kindCapsule) {
            // A capsule is a box along its segment, rounded by its radius.
            vec2 along = geomA.zw - geomA.xy;
            float len = length(along);
            if (len > 0.0) axis = along / len;
            centre = 0.5 * (geomA.xy + geomA.zw);
            halfExtents = vec2(0.5 * len + geomB.x, geomB.x);
            cornerRadius = geomB.x;
            if (((kindAndFlags >> 8u) & 1u) == 1u) vShapeC = jointPlane(geomA.xy, geomB.y);
            if (((kindAndFlags >> 9u) & 1u) == 1u) vShapeD = jointPlane(geomA.zw, geomB.z);
        } else {
            centre = geomA.xy;
            axis = geomB.xy;
            halfExtents = geomA.zw;
            cornerRadius = geomB.z;
        }
        vShapeA = vec4(centre, axis);
        vShapeB = vec4(halfExtents, cornerRadius, outlineWidth);
        vec2 local = corner * (halfExtents + margin);
        p = centre + axis * local.x + vec2(-axis.y, axis.x) * local.y;
    }
    gl_Position = vec4(p / frameSize * 2.0 - 1.0, 0.0, 1.0);
    vFill = fillColour;
    vOutline = outlineColour;
}
