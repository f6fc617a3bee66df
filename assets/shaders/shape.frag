#version 330 core
// Analytic antialiasing: each shape has a signed distance d in pixels (negative inside), and a
// pixel's coverage is clamp(0.5 - d, 0, 1), a one-pixel box filter across the edge. No MSAA,
// no textures: the result depends only on the instance data, so frames are deterministic.
// Discs, capsules and boxes are all one shape, a rotated box with rounded corners; triangles
// (polygons, arrow heads) are three edge planes. Both are cheap, and llvmpipe evaluates both
// for every pixel anyway (see shape.vert), so there is nothing to gain from more kinds.

flat in vec4 vShapeA;
flat in vec4 vShapeB;
flat in vec4 vShapeC;
flat in vec4 vShapeD;
flat in uint vIsTriangle;
flat in vec4 vFill;
flat in vec4 vOutline;

out vec4 fragColour;  // premultiplied alpha, blended with (ONE, ONE_MINUS_SRC_ALPHA)

// Distance to a box of half extents h, corners rounded by r, in the box's own frame:
// outside, the length of the positive excess; inside, the largest (least negative) excess.
float roundedBoxDistance(vec2 local, vec2 h, float r) {
    vec2 excess = abs(local) - (h - r);
    return length(max(excess, 0.0)) + min(max(excess.x, excess.y), 0.0) - r;
}

// One edge's share of a triangle's coverage (see edgePlane in shape.vert): boundary edges
// are antialiased, shared edges are hard and owned by exactly one of their two triangles.
float edgeCoverage(vec4 plane, vec2 p) {
    float d = dot(plane.xy, p) - plane.z;
    if (plane.w == 0.0) return clamp(0.5 - d, 0.0, 1.0);
    return (plane.w > 0.0 ? d >= 0.0 : d < 0.0) ? 1.0 : 0.0;
}

void main() {
    vec2 p = gl_FragCoord.xy;
    float coverage;
    float inner = 1.0;  // share of the pixel inside the outline band, where the fill shows
    if (vIsTriangle == 1u) {
        coverage = min(min(edgeCoverage(vShapeA, p), edgeCoverage(vShapeB, p)), edgeCoverage(vShapeC, p));
    } else {
        vec2 axis = vShapeA.zw;
        vec2 d = p - vShapeA.xy;
        vec2 local = vec2(dot(d, axis), dot(d, vec2(-axis.y, axis.x)));
        float distance = roundedBoxDistance(local, vShapeB.xy, vShapeB.z);
        // A chained stroke stops at the bisector of each joint: the two pieces meet without
        // overlapping, so translucent trails show no darker beads at their joints.
        bool kept = dot(vShapeC.xy, p) - vShapeC.z >= 0.0 && dot(vShapeD.xy, p) - vShapeD.z < 0.0;
        coverage = kept ? clamp(0.5 - distance, 0.0, 1.0) : 0.0;
        float outlineWidth = vShapeB.w;
        if (outlineWidth > 0.0) {
            inner = clamp(0.5 - (distance + outlineWidth), 0.0, 1.0);
        }
    }
    vec4 fill = vec4(vFill.rgb * vFill.a, vFill.a);
    vec4 outline = vec4(vOutline.rgb * vOutline.a, vOutline.a);
    fragColour = mix(outline, fill, inner) * coverage;
}
