#version 450
// The shadow pass writes depth only; OpenGL 3.3 links no program without a
// fragment stage, so it gets this empty one (Vulkan too: one pipeline shape).
void main() {}
