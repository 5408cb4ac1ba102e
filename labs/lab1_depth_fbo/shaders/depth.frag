#version 330 core
// Lab 1: the depth pass's fragment shader has nothing to do. The depth test
// writes gl_FragCoord.z into the depth attachment; there is no colour output.
void main() {
}
