// A compute invocation's place in a dispatch over list entries, laid out in
// rows of VOXEL_LIST_ROW workgroups (shared/voxel_list_pass.h).

uint listGroupIndex() { return gl_WorkGroupID.y * VOXEL_LIST_ROW + gl_WorkGroupID.x; }
uint listInvocation() { return listGroupIndex() * VOXEL_LIST_GROUP + gl_LocalInvocationID.x; }
