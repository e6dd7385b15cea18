// Exact triangle / closed voxel box overlap by the separating-axis theorem
// (Akenine-Moeller). Double precision with the very operations, in the very
// order, of the CPU reference (tests/vxgi/sat.cpp), and `precise` so no
// multiply-add is fused: given the same float vertices both decide every tie
// (a triangle touching a voxel's face, edge or corner) alike. Needs
// shaderFloat64.

dvec3 crossExact(dvec3 x, dvec3 y) {  // glm::cross's operation order
    precise dvec3 r = dvec3(x.y * y.z - y.y * x.z, x.z * y.x - y.z * x.x, x.x * y.y - y.x * x.y);
    return r;
}

// Triangle vertices relative to the box centre; the box is [-h, h]^3.
bool separatedOn(dvec3 axis, dvec3 v0, dvec3 v1, dvec3 v2) {
    precise double p0 = (axis.x * v0.x + axis.y * v0.y) + axis.z * v0.z;
    precise double p1 = (axis.x * v1.x + axis.y * v1.y) + axis.z * v1.z;
    precise double p2 = (axis.x * v2.x + axis.y * v2.y) + axis.z * v2.z;
    const double h = 0.5LF + double(VOXC_BOX_GROWTH);  // the grown half-size
    precise double r = (h * abs(axis.x) + h * abs(axis.y)) + h * abs(axis.z);
    return min(p0, min(p1, p2)) > r || max(p0, max(p1, p2)) < -r;
}

// The three axes e x (1,0,0), e x (0,1,0), e x (0,0,1), written out as glm computes them.
bool separatedAcrossEdge(dvec3 e, dvec3 v0, dvec3 v1, dvec3 v2) {
    return separatedOn(dvec3(0.0LF, e.z, -e.y), v0, v1, v2) || separatedOn(dvec3(-e.z, 0.0LF, e.x), v0, v1, v2) ||
           separatedOn(dvec3(e.y, -e.x, 0.0LF), v0, v1, v2);
}

// p0..p2: the triangle in voxel units; e0..e2: its edges p1 - p0, p2 - p1,
// p0 - p2; n: crossExact(e0, e1). The three box axes are not tested: callers
// ask only about voxels whose grown box meets the triangle's bounding box,
// which they cannot separate. Vectors rather than arrays (see voxelize.comp's
// Triangle: by-value arrays measured slower on lavapipe).
bool triangleTouchesVoxel(dvec3 p0, dvec3 p1, dvec3 p2, dvec3 e0, dvec3 e1, dvec3 e2, dvec3 n, ivec3 voxel) {
    dvec3 c = dvec3(voxel) + 0.5LF;
    dvec3 v0 = p0 - c, v1 = p1 - c, v2 = p2 - c;  // exact: float coordinates, half-integer centre
    return !separatedOn(n, v0, v1, v2) && !separatedAcrossEdge(e0, v0, v1, v2) &&
           !separatedAcrossEdge(e1, v0, v1, v2) && !separatedAcrossEdge(e2, v0, v1, v2);
}
