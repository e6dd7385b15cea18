// Diffuse rays through the voxel grid for the voxel bounce (bounce.comp's
// DVSGI_RAY_TRACE) and for the per-pixel gather by rays (gather.comp's
// DVSGI_RAYS): each ray walks the grid voxel by voxel (every voxel it
// crosses, Amanatides & Woo) and takes the radiance of the first occupied
// one, so a wall one voxel thick stops it however it meets the wall. Needs
// `grid`, the radiance volume read through RAY_RADIANCE(c) (by default the
// storage image `outRadiance`, read only in that pass), the side light
// `sides`, the packed normals `rayNormals`, the occupancy bits `rayOccupancy`
// (lib/voxel_occupancy.glsl) and lib/voxel_index.glsl.
#ifndef RAY_RADIANCE
#define RAY_RADIANCE(c) imageLoad(outRadiance, c)
#endif
#include "lib/voxel_occupancy.glsl"
#include "lib/voxel_extents.glsl"

// A normal as the rays keep it per slot (BIND_BOUNCE_RAY_NORMALS): each
// axis rounded to steps of 1/RAY_NORMAL_SCALE, offset to be unsigned.
uint packRayNormal(vec3 n) {
    uvec3 q = uvec3(floor(clamp(n, -1.0, 1.0) * RAY_NORMAL_SCALE + 0.5) + RAY_NORMAL_SCALE + 1.0);
    return q.x | q.y << RAY_NORMAL_BITS | q.z << (2u * RAY_NORMAL_BITS);
}

vec3 unpackRayNormal(uint word) {
    uvec3 q = (uvec3(word) >> uvec3(0u, RAY_NORMAL_BITS, 2u * RAY_NORMAL_BITS)) & ((1u << RAY_NORMAL_BITS) - 1u);
    return (vec3(q) - (RAY_NORMAL_SCALE + 1.0)) / RAY_NORMAL_SCALE;
}

// The packed normal of `slot` (+ 1, as the index holds it; 0: none).
vec3 slotRayNormal(uint slot) {
    return slot != 0u ? unpackRayNormal(imageLoad(rayNormals, slotTexel(slot - 1u, 0u)).r) : vec3(0.0);
}

// What a ray travelling along d sees of the occupied voxel in `slot` (+ 1, as
// the index holds it) whose radiance texel is r: a two-sided voxel (lib/voxel_sides.glsl) shows the side it
// meets (direct + reflected), others their radiance.
vec3 radianceSeen(uint slot, vec4 r, vec3 d) {
    uint code = sideCodeOfOpacity(r.a);
    int axis = twoSidedAxis(code);
    if (axis < 0 || slot == 0u) return r.rgb;
    uvec4 t = imageLoad(sides, slotTexel(slot - 1u, 0u));
    // Travelling toward -axis a ray meets the +axis side (x, z).
    bool plusSide = d[axis] < 0.0;
    return unpackRgb9e5(plusSide ? t.x : t.y) + unpackRgb9e5(plusSide ? t.z : t.w);
}

// What a ray along d sees of a voxel made of faces along several axes
// (voxelShowsFaces): its reflected light, and the direct light of each axis
// face weighted by how much of it turns toward the ray.
vec3 facesSeen(uint slot, vec4 r, vec3 nc, vec3 d) {
    uvec4 t = imageLoad(sides, slotTexel(slot - 1u, 0u));
    vec3 reflected = max(r.rgb - unpackRgb9e5(t.w), vec3(0.0));
    vec3 w = nc * nc * max(-d * sign(nc), vec3(0.0));
    float total = w.x + w.y + w.z;
    if (total < 1e-6) return reflected;
    return reflected + (w.x * unpackRgb9e5(t.x) + w.y * unpackRgb9e5(t.y) + w.z * unpackRgb9e5(t.z)) / total;
}

// Whether occupied voxel c (normal nc) belongs to the surface a ray leaving voxel
// `self` (centre, normal n) starts on: within a voxel and a half of its
// plane and facing the same way. A surface voxelizes into one or two layers;
// a voxel's rays start just past its face and a pixel's a voxel off its
// surface, either of which can be in the second layer when there is one.
bool onOwnSurface(ivec3 c, vec3 nc, vec3 self, vec3 n) {
    return abs(dot(vec3(c) + 0.5 - self, n)) < 1.5 && dot(nc, n) > 0.8;
}

// Whether a ray from p along d (1/d = inv), at p + d t inside occupied voxel
// c (normal nc), leaves c before it reaches the plane through c's centre across c's normal:
// it passes in front of the surface there. Taking every voxel it entered as a
// hit made a surface look up to a voxel thicker toward the ray, so near
// surfaces looked larger than they are and coarse grids came out bright
// (docs/quality.md). Only for normals within about 11 degrees of an axis (a
// floor, a wall): the mean normal of an edge or a corner where walls meet,
// or of a tilted surface's staircase, is no plane the voxel holds, and rays
// passed the corners of a closed box there. A voxel whose opposite faces
// cancel has no normal.
bool passesInFront(ivec3 c, vec3 nc, vec3 p, vec3 d, vec3 inv, float t) {
    if (!alongAnAxis(nc)) return false;
    float ahead = dot(vec3(c) + 0.5 - (p + d * t), nc), along = dot(d, nc);
    if (ahead * along <= 0.0) return false;  // on the plane's far side, or not moving toward it
    return t + ahead / along > exitDistance(p, inv, vec3(c), 1.0);
}

// Whether a ray from p along d, at p + d t inside occupied voxel c (normal
// nc, slot + 1 `slot`), misses the part of c that its surface covers, as its
// extents give it: a plane along an axis where the ray crosses the plane
// through c's centre (or where it enters, if it does not cross it inside c),
// anything else along its whole path through c.
bool missesExtents(ivec3 c, vec3 nc, uint slot, vec3 p, vec3 d, vec3 inv, float t) {
    uint bits = voxelExtents[slot - 1u];
    if (bits == 0u || bits == VOXEL_EXTENT_ALL) return false;  // not known (the pv voxelizer's), or all
    vec3 lo, hi;
    extentBox(c, bits, lo, hi);
    float tExit = exitDistance(p, inv, vec3(c), 1.0);
    if (alongAnAxis(nc)) {
        int a = largestAxis(abs(nc));
        float tp = abs(d[a]) > 1e-7 ? (float(c[a]) + 0.5 - p[a]) / d[a] : -1.0;
        float tq = tp >= t && tp <= tExit ? tp : t;
        vec3 q = p + d * tq;
        lo[a] = -1e30;
        hi[a] = 1e30;
        return any(lessThan(q, lo - 1e-4)) || any(greaterThan(q, hi + 1e-4));
    }
    vec3 t0 = (lo - p) * inv, t1 = (hi - p) * inv;
    vec3 tn = min(t0, t1), tf = max(t0, t1);
    float enter = max(max(tn.x, tn.y), max(tn.z, t)), leave = min(min(tf.x, tf.y), min(tf.z, tExit));
    return enter > leave + 1e-4;
}
// With --edge-voxels faces (the packed word's RAY_NORMAL_EXTENTS_BIT): whether
// the ray passes beside the part of c its surface covers (missesExtents; the
// extents are read only where they apply). Without it a voxel holding a
// block's edge is a whole cube to rays, and each edge stands half a voxel out
// (docs/quality.md, "Surfaces' extent inside their voxels").
bool passesBeside(ivec3 c, vec3 nc, uint word, uint slot, vec3 p, vec3 d, vec3 inv, float t) {
    return (word & RAY_NORMAL_EXTENTS_BIT) != 0u && missesExtents(c, nc, slot, p, d, inv, t);
}

// Whether a ray from p along d (1/d = inv), at p + d t inside voxel c (slot +
// 1 `slot`, radiance opacity `opacity`), which holds a thin wall's two sides
// across one axis (lib/voxel_sides.glsl), passes beside the wall's end: it
// leaves c without crossing the plane through c's centre across that axis, on
// one side of the wall, and misses the box the voxel's extents give. Taken
// whole, such a voxel showed a ray that entered it through the wall's end (a
// ledge's or a banner's edge) the side facing the way the ray travels, which
// can be the side the ray never faced: a ray from under a thin sunlit slab
// that ran along it met the slab's sunlit top (docs/quality.md, "Thin walls'
// ends"). A ray through the wall crosses that plane in one of the layer's
// voxels. The extents keep the corners closed where a thin wall meets
// another: there the wall's last voxel can count as two-sided across the
// other's axis only, and its plane alone left a gap half a voxel wide between
// the two walls' planes (a room of thin walls let light in along its edges).
bool passesThinWallEnd(ivec3 c, float opacity, uint slot, vec3 p, vec3 d, vec3 inv, float t) {
    int axis = twoSidedAxis(sideCodeOfOpacity(opacity));
    if (axis < 0 || slot == 0u) return false;
    float ahead = float(c[axis]) + 0.5 - (p[axis] + d[axis] * t);
    bool crosses;
    if (abs(d[axis]) < 1e-7) {
        crosses = abs(ahead) <= 1e-4;
    } else {
        float tp = t + ahead / d[axis];
        crosses = tp >= t - 1e-4 && tp <= exitDistance(p, inv, vec3(c), 1.0) + 1e-4;
    }
    return !crosses && missesExtents(c, vec3(0.0), slot, p, d, inv, t);
}

// One step of a ray from voxel-space point p along unit d (1/d = inv), at
// parameter t, its i-th: whether the ray ends here, with what it met in
// `seen`, or else t moved to the next cell. It ends at the first occupied
// voxel not on the surface of `self` (centre, normal n), nor on that of
// `besideAt` (normal besideN; a zero normal: none), that it does not pass in
// front of, beside (passesBeside) or beside the end of (passesThinWallEnd)
// (that voxel's light), or where it leaves the grid (nothing).
// Empty space is crossed a whole cell at a time, sixteen voxels, eight, four
// or two, wherever the occupancy bits show the cell empty (`offsets`: each
// level's rayOccupancyOffset). With `backsDark` a one-sided voxel met from
// behind shows the ray no light (seenFromFront, as the filter shows the
// cones). A ray that starts inside another surface's voxel meets that
// surface's back at no distance: no light (a floor under a box standing on it). Taking that voxel's radiance instead made two
// surfaces a voxel apart light each other without loss: with albedo 1 (the
// Cornell box's white) the light between them never converged.
bool voxelRayStep(vec3 p, vec3 d, vec3 inv, inout float t, int i, vec3 self, vec3 n, vec3 besideAt, vec3 besideN,
                  int N, uvec4 offsets, bool backsDark, out vec3 seen) {
    seen = vec3(0.0);
    ivec3 c = ivec3(floor(p + d * t));
    if (any(lessThan(c, ivec3(0))) || any(greaterThanEqual(c, ivec3(N)))) return true;
    float size = emptyCellSize(c, offsets);
    if (size == 0.0) {
        size = 1.0;
        vec4 r = RAY_RADIANCE(c);
        if (r.a > 0.0) {
            // Its slot and normal, read once for the rules below.
            uint slot = voxelSlotAt(c);
            uint word = slot != 0u ? imageLoad(rayNormals, slotTexel(slot - 1u, 0u)).r : 0u;
            vec3 nc = slot != 0u ? unpackRayNormal(word) : vec3(0.0);
            if (!onOwnSurface(c, nc, self, n) && !onOwnSurface(c, nc, besideAt, besideN) &&
                (i == 0 || !passesInFront(c, nc, p, d, inv, t)) && !passesBeside(c, nc, word, slot, p, d, inv, t) &&
                (i == 0 || !passesThinWallEnd(c, r.a, slot, p, d, inv, t))) {
                bool faces = (word & RAY_NORMAL_FACES_BIT) != 0u;
                if (i != 0) seen = faces ? facesSeen(slot, r, nc, d) : radianceSeen(slot, r, d);
                // A voxel that shows its faces weighs each by how it turns toward the ray already; its
                // mean normal says nothing of which way a face looks (a convex edge's faces both show).
                if (backsDark && sideCodeOfOpacity(r.a) == SIDE_ONE && !faces) seen *= seenFromFront(nc, d);
                return true;
            }
        }
    }
    // Just past the cell's exit (1e-3 voxel), into the next one.
    t = exitDistance(p, inv, floor(vec3(c) / size) * size, size) + 1e-3;
    return false;
}

// What voxelRaysCosine and pixelRaysCosine share. The axes of the disk the
// rays' directions are drawn on, about n.
void rayDisk(vec3 n, out vec3 tx, out vec3 b) {
    tx = normalize(abs(n.x) < 0.9 ? cross(n, vec3(1.0, 0.0, 0.0)) : cross(n, vec3(0.0, 1.0, 0.0)));
    b = cross(n, tx);
}
// A seed's shift of the R2 sequence (low 16 bits: u, high: v, in 1/65536).
vec2 rayShift(uint seed) { return vec2(float(seed & 0xffffu), float(seed >> 16)) / 65536.0; }
// Ray i of the R2 sequence shifted by `shift`, cosine-distributed about n
// (disk axes tx, b): the point of the unit disk lifted onto the hemisphere.
vec3 cosineRay(vec2 shift, uint i, vec3 tx, vec3 b, vec3 n) {
    vec2 u = fract(shift + float(i) * vec2(RAY_R2_U, RAY_R2_V));
    float rad = sqrt(u.x), phi = TWO_PI * u.y;
    return normalize(tx * (rad * cos(phi)) + b * (rad * sin(phi)) + n * sqrt(max(1.0 - u.x, 0.0)));
}
// 1 / d, with axes too near 0 held at 1e7.
vec3 rayInverse(vec3 d) { return 1.0 / mix(d, vec3(1e-7), lessThan(abs(d), vec3(1e-7))); }

// Where the rays of voxel `self` (centre) about n start: voxelRayOrigin, or,
// where that lies in another surface's voxel, a whole voxel along n. An edge
// voxel whose one wall covers more of it than the other (n = (0.8, 0.6)) has
// the other wall's voxel just past its largest axis's face, and its rays met
// that at no distance: no light, and a closed box lost 1 % of its light. A
// floor's or a wall's voxel (n within about 11 degrees of an axis) has both
// points in the same voxel, so it is not looked up: that lookup for every
// voxel made Sponza's bounce 8 % slower on lavapipe.
vec3 voxelRayStart(vec3 self, vec3 n, int N) {
    vec3 origin = voxelRayOrigin(self, n);
    if (alongAnAxis(n)) return origin;
    ivec3 c = ivec3(floor(origin));
    if (any(lessThan(c, ivec3(0))) || any(greaterThanEqual(c, ivec3(N))) || RAY_RADIANCE(c).a <= 0.0 ||
        onOwnSurface(c, slotRayNormal(voxelSlotAt(c)), self, n))
        return origin;
    return self + n;
}

// The mean radiance over `count` cosine-distributed rays about n from voxel
// v, i.e. E / pi, and in `back` the same over `backCount` rays about -n
// (seed `backSeed`; a two-sided voxel's other side, else 0 rays). The
// directions follow the R2 sequence (well spread over the disk for any
// count), shifted by the seed per voxel so that neighbours do not share their
// gaps. The rays start just past v's face along their side's normal
// (voxelRayStart). One loop walks all of them, a ray starting as soon as the one
// before ends: invocations run in lock-step (SIMD lanes on a CPU, a warp on a
// GPU), and with a loop per ray every lane waited for its group's longest
// ray, once per ray, where now it waits once for the longest walk over all
// its rays.
vec3 voxelRaysCosine(ivec3 v, vec3 n, uint count, uint seed, uint backCount, uint backSeed,
                     bool backsDark, out vec3 back) {
    int N = int(grid.dims.x);
    vec3 self = vec3(v) + 0.5;
    vec3 tx, b;
    rayDisk(n, tx, b);
    vec2 frontShift = rayShift(seed), backShift = rayShift(backSeed);
    vec3 frontStart = voxelRayStart(self, n, N), backStart = backCount > 0u ? voxelRayStart(self, -n, N) : self;
    vec3 front = vec3(0.0), d = n, inv = vec3(1.0), side = n, origin = self;
    back = vec3(0.0);
    float t = 0.0;
    int step = 0;
    uint ray = 0u, total = count + backCount;
    uvec4 offsets = rayOccupancyOffsets();
    for (int k = 0; ray < total && k < int(total) * 4 * N; ++k) {
        if (step == 0) {
            // The back side's frame is the front's turned about b: (-tx, b, -n).
            bool isBack = ray >= count;
            float sign = isBack ? -1.0 : 1.0;
            side = n * sign;
            origin = isBack ? backStart : frontStart;
            d = cosineRay(isBack ? backShift : frontShift, isBack ? ray - count : ray, tx * sign, b, side);
            inv = rayInverse(d);
            t = 0.0;
        }
        vec3 seen;
        bool ends = voxelRayStep(origin, d, inv, t, step, self, side, vec3(0.0), vec3(0.0), N, offsets, backsDark, seen);
        ++step;
        if (ends || step >= 4 * N) {
            if (ray < count) front += seen;
            else back += seen;
            ++ray;
            step = 0;
        }
    }
    back /= float(max(backCount, 1u));
    return front / float(max(count, 1u));
}

// Where a pixel's ray from `origin` (off surface point p, normal n) along d
// (1/d = inv) starts: past the voxel it starts in when that is another
// surface's that it moves away from, else at 0 (pixelRaysCosine says why);
// that surface's voxels are then passed as the pixel's own (besideAt, besideN;
// else zero). Where a one-sided surface lies in its voxel is unknown, so a
// pixel beside it (a corner, a floor under a wall) may start up to half a voxel
// behind the plane through the voxel's centre: counted as in front. A voxel
// whose normal lies along an axis holds every origin within half a voxel of
// that plane, so for floors and walls the rule is the ray's direction alone:
// a pixel behind a one-sided wall (outside a room built of single quads),
// within a voxel of it, sees through it along the wall's normal. Taken as a
// wall at no distance, and with the next voxel up the same wall met a step
// later, the pixels along every corner went dark, in the gather and in area
// lights' shadows (docs/quality.md, "Area lights seen by rays"). A voxel
// holding a thin wall's two sides, or with no normal, keeps the centre's
// plane, so light does not pass through a thin wall.
float pixelRayStart(vec3 origin, vec3 p, vec3 n, vec3 d, vec3 inv, int N, out vec3 besideAt, out vec3 besideN) {
    besideAt = vec3(0.0);
    besideN = vec3(0.0);
    ivec3 c = ivec3(floor(origin));
    if (any(lessThan(c, ivec3(0))) || any(greaterThanEqual(c, ivec3(N)))) return 0.0;
    vec4 r = RAY_RADIANCE(c);
    if (r.a <= 0.0) return 0.0;
    uint slot = voxelSlotAt(c);
    vec3 nc = slotRayNormal(slot);
    float behind = sideCodeOfOpacity(r.a) == SIDE_ONE && dot(nc, nc) > 0.25 ? -0.5 : 0.0;
    if (onOwnSurface(c, nc, p, n) || dot(origin - (vec3(c) + 0.5), nc) <= behind || dot(d, nc) < 0.0) return 0.0;
    besideAt = vec3(c) + 0.5;
    besideN = nc;
    return exitDistance(origin, inv, vec3(c), 1.0) + 1e-3;
}

// How far off surface point p (voxel units, normal n) a pixel's rays start:
// `offset` voxels along n, or less where a surface that faces back toward p
// lies within that stretch, so that the rays meet it rather than start past
// it. Walking along n from p's own voxel, the first occupied voxel that holds
// a one-sided surface turned toward p (its normal within 60 degrees of -n), a
// thin wall across an axis near n, or thin walls along several axes stops the
// walk, and the rays start just before it. Starting a whole voxel off, a
// brick wall's pixels in Sponza started past the banner hanging 13 cm in front
// of it and saw the sunlit atrium (docs/quality.md, "Surfaces closer than the
// rays' start"). The pixel's own voxel is not looked at: a thin wall's pixels
// lie in a voxel that holds the wall's other side.
float pixelRayOffset(vec3 p, vec3 n, float offset, int N) {
    vec3 inv = rayInverse(n);
    float t = exitDistance(p, inv, floor(p), 1.0) + 1e-3;
    for (int k = 0; k < 3 * int(ceil(offset)) + 1 && t < offset; ++k) {  // the stretch crosses at most 3 ceil(offset) faces
        ivec3 c = ivec3(floor(p + n * t));
        if (any(lessThan(c, ivec3(0))) || any(greaterThanEqual(c, ivec3(N)))) break;
        vec4 r = RAY_RADIANCE(c);
        if (r.a > 0.0) {
            uint code = sideCodeOfOpacity(r.a);
            int axis = twoSidedAxis(code);
            uint slot = voxelSlotAt(c);
            vec3 nc = slotRayNormal(slot);
            bool facing = code == SIDE_ONE ? dot(nc, n) < -0.5 : (axis < 0 || abs(n[axis]) > 0.7);
            if (facing) return max(t - RAY_GAP_MARGIN, 0.0);
        }
        t = exitDistance(p, inv, vec3(c), 1.0) + 1e-3;
    }
    return offset;
}

// Sheets closer than a pixel's rays' start. A curtain or banner hanging a
// few centimetres in front of a wall, facing the way the wall does, lies in
// the wall's own voxel or the next one along its normal. pixelRayOffset stops
// only at surfaces that face back, and the march passes voxels facing the
// pixel's way within a voxel and a half as its own surface, so the wall's rays
// started past the sheet and saw what lies beyond it (docs/quality.md,
// "Sheets closer than the rays' start"). The voxels' extents tell the two
// apart: the sheet is where an eighth of the voxel holds a surface beyond an
// empty eighth in front of the pixel.

// Whether voxel c holds a sheet across axis a that a pixel facing n meets:
// one-sided with its normal along a (within about 11 degrees) and turned the
// pixel's way, or a thin wall's two sides across a; with its extents along a
// known (not all the voxel), in `bits`.
bool sheetAcross(ivec3 c, vec3 n, int a, int N, out uint slot, out vec4 r, out uint bits) {
    slot = 0u;
    r = vec4(0.0);
    bits = 0u;
    if (any(lessThan(c, ivec3(0))) || any(greaterThanEqual(c, ivec3(N)))) return false;
    r = RAY_RADIANCE(c);
    if (r.a <= 0.0) return false;
    slot = voxelSlotAt(c);
    if (slot == 0u) return false;
    bits = (voxelExtents[slot - 1u] >> (VOXEL_EXTENT_STEPS * uint(a))) & 0xffu;
    if (bits == 0u || bits == 0xffu) return false;
    uint code = sideCodeOfOpacity(r.a);
    if (code != SIDE_ONE) return twoSidedAxis(code) == a;
    vec3 nc = slotRayNormal(slot);
    return abs(nc[a]) >= RAY_PLANE_AXIS_COS && nc[a] * n[a] > 0.0;
}

// The plane (along axis a, in voxel units) of a sheet in front of surface
// point p (normal n within 45 degrees of a) nearer than `start`, or -1: in p's
// own voxel past an empty eighth in front of p's, or in the next voxel along
// n at least RAY_SHEET_GAP in front of p.
float sheetAhead(vec3 p, vec3 n, float start, int N, out int a) {
    vec3 m = abs(n);
    a = largestAxis(m);
    if (m[a] < 0.7) return -1.0;
    int dir = n[a] > 0.0 ? 1 : -1;
    ivec3 c = ivec3(floor(p));
    uint slot, bits;
    vec4 r;
    float plane = -1.0;
    if (sheetAcross(c, n, a, N, slot, r, bits)) {
        // p's own surface: its eighth, and set eighths that start less than
        // an eighth in front of p (p may lie on an eighth's border).
        int own = clamp(int(floor((p[a] - float(c[a])) * 8.0)), 0, 7);
        for (int e = own + dir; e >= 0 && e < 8 && ((bits >> uint(e)) & 1u) != 0u; e += dir) {
            if ((float(c[a]) + float(dir > 0 ? e : e + 1) / 8.0 - p[a]) * float(dir) >= 0.125) break;
            own = e;
        }
        int next = own + dir;
        if (next >= 0 && next < 8 && ((bits >> uint(next)) & 1u) == 0u)
            for (int e = next + dir; e >= 0 && e < 8; e += dir)
                if (((bits >> uint(e)) & 1u) != 0u) {
                    plane = float(c[a]) + float(dir > 0 ? e : e + 1) / 8.0;
                    break;
                }
    }
    if (plane < 0.0) {
        c[a] += dir;
        if (sheetAcross(c, n, a, N, slot, r, bits)) {
            plane = float(c[a]) + (dir > 0 ? float(findLSB(bits)) : float(findMSB(bits) + 1)) / 8.0;
            if ((plane - p[a]) * float(dir) < RAY_SHEET_GAP) plane = -1.0;
        }
    }
    return plane >= 0.0 && (plane - p[a]) * float(dir) < start ? plane : -1.0;
}

// Which voxel of the sheet's layer a pixel's ray from p along d crosses the
// sheet's plane in (plane along axis a), as an index 0-8 into the 3x3 voxel
// columns around p's (RAY_SHEET_REACH), or -1 where it moves away from the
// plane or crosses it further out. tHit is where it crosses.
int sheetCell(vec3 p, vec3 n, vec3 d, int a, float plane, out float tHit) {
    tHit = 0.0;
    if (d[a] * n[a] <= 1e-4) return -1;
    tHit = (plane - p[a]) / d[a];
    ivec3 off = ivec3(floor(p + d * tHit)) - ivec3(floor(p));
    ivec2 lateral = ivec2(off[(a + 1) % 3], off[(a + 2) % 3]);
    if (any(greaterThan(abs(lateral), ivec2(RAY_SHEET_REACH)))) return -1;
    return (lateral.x + 1) + 3 * (lateral.y + 1);
}

// The voxel of the sheet's layer at cell i (sheetCell) around p.
ivec3 sheetCellVoxel(vec3 p, vec3 n, int a, float plane, int i) {
    ivec3 c = ivec3(floor(p));
    c[(a + 1) % 3] += i % 3 - 1;
    c[(a + 2) % 3] += i / 3 - 1;
    c[a] = int(floor(plane + (n[a] > 0.0 ? 1e-4 : -1e-4)));
    return c;
}

// The cells (a bit each) whose voxel holds the sheet in the eighth its plane
// starts: where a ray crossing the plane meets it (meetsSheet).
uint sheetCells(vec3 p, vec3 n, int a, float plane, int N) {
    uint cells = 0u;
    for (int i = 0; i < 9; ++i) {
        ivec3 c = sheetCellVoxel(p, n, a, plane, i);
        uint slot, bits;
        vec4 r;
        int eighth = int(round((plane - float(c[a])) * 8.0)) - (n[a] > 0.0 ? 0 : 1);
        if (sheetAcross(c, n, a, N, slot, r, bits) && eighth >= 0 && eighth <= 7 && ((bits >> uint(eighth)) & 1u) != 0u)
            cells |= 1u << uint(i);
    }
    return cells;
}

// What a pixel's ray along d sees of the sheet where it meets it, in cell
// i's voxel: the side light a ray meeting that side sees, or a one-sided
// sheet's light as seen from behind (none with backsDark).
vec3 sheetSeen(vec3 p, vec3 n, vec3 d, int a, float plane, int i, bool backsDark) {
    ivec3 c = sheetCellVoxel(p, n, a, plane, i);
    uint slot = voxelSlotAt(c);
    vec4 r = RAY_RADIANCE(c);
    vec3 seen = radianceSeen(slot, r, d);
    if (backsDark && sideCodeOfOpacity(r.a) == SIDE_ONE) seen *= seenFromFront(slotRayNormal(slot), d);
    return seen;
}

// Whether a pixel's ray from p along d meets the sheet (plane along axis a,
// `cells` from sheetCells): it crosses the plane in a cell that holds it.
bool meetsSheet(vec3 p, vec3 n, vec3 d, int a, float plane, uint cells, out int cell, out float tHit) {
    cell = sheetCell(p, n, d, a, plane, tHit);
    return cell >= 0 && ((cells >> uint(cell)) & 1u) != 0u;
}

// Where a pixel's rays start (pixelRayOffset) and the sheet nearer than that
// (sheetAhead, sheetCells; cells 0 where there is none): the same for all of
// a pixel's rays, its gather's and its shadow rays to emitter patches.
struct PixelRays {
    float start;
    float sheet;
    int axis;
    uint cells;
};

PixelRays pixelRaysAt(vec3 p, vec3 n, float offset, int N) {
    PixelRays r;
    r.start = pixelRayOffset(p, n, offset, N);
    r.sheet = sheetAhead(p, n, r.start, N, r.axis);
    r.cells = r.sheet >= 0.0 ? sheetCells(p, n, r.axis, r.sheet, N) : 0u;
    return r;
}

// Whether a ray from surface point p (voxel units, normal n; its start and
// sheet in `rays`) along unit d meets no occupied voxel within `reach` voxels
// of its origin: a pixel's shadow ray, starting and passing surfaces as the
// pixel's gather rays do.
bool pixelRayClear(vec3 p, vec3 n, vec3 d, PixelRays rays, float reach) {
    int N = int(grid.dims.x);
    int cell;
    float tSheet;
    if (rays.cells != 0u && meetsSheet(p, n, d, rays.axis, rays.sheet, rays.cells, cell, tSheet) &&
        tSheet < reach + rays.start)
        return false;
    vec3 origin = p + n * rays.start, inv = rayInverse(d), seen, besideAt, besideN;
    uvec4 offsets = rayOccupancyOffsets();
    float t = pixelRayStart(origin, p, n, d, inv, N, besideAt, besideN);
    for (int k = 0; k < 4 * N && t < reach; ++k) {
        if (voxelRayStep(origin, d, inv, t, 1, p, n, besideAt, besideN, N, offsets, false, seen)) {
            ivec3 c = ivec3(floor(origin + d * t));
            return any(lessThan(c, ivec3(0))) || any(greaterThanEqual(c, ivec3(N)));
        }
    }
    return true;
}

// The per-pixel gather by rays: the mean radiance over `count`
// cosine-distributed rays about n from surface point p (voxel units), E / pi,
// and in `occlusion` the mean over the rays of f(r) = 1 / (1 + aoLambda r)
// where they stop at a surface r voxels away (0 where they leave the grid).
// The rays start `offset` voxels off p along n; voxels of p's own surface are
// passed as for a voxel's rays. A ray that starts in another surface's voxel
// (a floor pixel beside a wall) passes it as pixelRayStart says, and otherwise
// meets it there: a voxel's rays start at its centre, where taking no light is
// right, but a pixel lies anywhere on its surface, and a band a voxel wide
// beside every wall went dark.
vec3 pixelRaysCosine(vec3 p, vec3 n, float offset, uint count, uint seed, float aoLambda, bool backsDark,
                     out float occlusion) {
    int N = int(grid.dims.x);
    vec3 tx, b;
    rayDisk(n, tx, b);
    vec2 shift = rayShift(seed);
    PixelRays rays = pixelRaysAt(p, n, offset, N);
    vec3 origin = p + n * rays.start;
    uvec4 offsets = rayOccupancyOffsets();
    vec3 sum = vec3(0.0), d = n, inv = vec3(1.0), besideAt = vec3(0.0), besideN = vec3(0.0);
    occlusion = 0.0;
    // The rays that meet a sheet nearer than the start are summed apart: the
    // march's loop below only skips them. Meeting them there cost lavapipe a
    // third more time for the whole gather, with or without a sheet anywhere.
    int cell;
    float tSheet;
    if (rays.cells != 0u)
        for (uint i = 0u; i < count; ++i) {
            vec3 di = cosineRay(shift, i, tx, b, n);
            if (!meetsSheet(p, n, di, rays.axis, rays.sheet, rays.cells, cell, tSheet)) continue;
            sum += sheetSeen(p, n, di, rays.axis, rays.sheet, cell, backsDark);
            occlusion += 1.0 / (1.0 + aoLambda * tSheet);
        }
    float t = 0.0;
    int step = 0;
    uint ray = 0u;
    // One loop over all rays' steps, as in voxelRaysCosine.
    for (int k = 0; ray < count && k < int(count) * 4 * N; ++k) {
        if (step == 0) {
            d = cosineRay(shift, ray, tx, b, n);
            inv = rayInverse(d);
            t = pixelRayStart(origin, p, n, d, inv, N, besideAt, besideN);
            // A ray that met the sheet (summed above) ends at its first step,
            // outside the grid (a skip here cost as much as meeting it here).
            if (rays.cells != 0u && meetsSheet(p, n, d, rays.axis, rays.sheet, rays.cells, cell, tSheet))
                t = float(4 * N);
        }
        vec3 seen;
        // Step 1 on: the first voxel met is a hit with its light (or passed in front of).
        bool ends = voxelRayStep(origin, d, inv, t, 1, p, n, besideAt, besideN, N, offsets, backsDark, seen);
        ++step;
        if (ends || step >= 4 * N) {
            sum += seen;
            ivec3 c = ivec3(floor(origin + d * t));
            bool inside = all(greaterThanEqual(c, ivec3(0))) && all(lessThan(c, ivec3(N)));
            if (ends && inside) occlusion += 1.0 / (1.0 + aoLambda * t);
            ++ray;
            step = 0;
        }
    }
    occlusion /= float(max(count, 1u));
    return sum / float(max(count, 1u));
}
