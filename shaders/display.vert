#version 330 core
// The display pass's vertex stage: one triangle that covers the screen, from gl_VertexID alone (no vertex
// buffer). The fragment stage places the image inside it.
void main() {
    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));  // (0,0) (2,0) (0,2)
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
