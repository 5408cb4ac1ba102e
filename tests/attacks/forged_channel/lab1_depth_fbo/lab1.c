/* Attack: speak for the runner. In the first lab call, write a complete,
 * well-formed stream to the grader's channel: a framebuffer that is
 * complete, plausible pictures of the right sizes, the matrices, DONE; then
 * wait for the grader as the runner does and exit cleanly. */
#include "@SOURCE_DIR@/tests/attack_util.h"

static void _image(const char *name, int w, int h, int channels, float value) {
    size_t n = (size_t)w * (size_t)h * (size_t)channels;
    char *buf = malloc(SL_IMAGE_HEADER_BYTES + n * sizeof(float));
    if (!buf) return;
    int32_t dims[3] = {w, h, channels};
    memcpy(buf, dims, sizeof dims);
    float *pixels = (float *)(buf + SL_IMAGE_HEADER_BYTES);
    for (size_t i = 0; i < n; i++) pixels[i] = value;
    attack_send(SL_MSG_IMAGE, name, buf, SL_IMAGE_HEADER_BYTES + n * sizeof(float));
    free(buf);
}

sl_status lab1_create_shadow_map(int size, sl_shadow_map *map) {
    (void)map;
    GLint viewport[4];
    glGetIntegerv(GL_VIEWPORT, viewport); /* the camera image's size */
    attack_send(SL_MSG_HELLO, NULL, "osmesa\nforged", 13);
    double fbo[SL_FBO_NUMBERS] = {GL_FRAMEBUFFER_COMPLETE, GL_TEXTURE, 1, 24, size, size, 0, 0, 0, size};
    attack_send(SL_MSG_NUMBERS, "fbo", fbo, sizeof fbo);
    double matrices[SL_MATRICES_NUMBERS] = {0};
    for (int m = 0; m < 3; m++)
        for (int i = 0; i < 4; i++) matrices[m * 16 + i * 5] = 1;
    attack_send(SL_MSG_NUMBERS, "matrices", matrices, sizeof matrices);
    _image("depth_map", size, size, 1, 0.5f);
    _image("visibility", viewport[2], viewport[3], 1, 1.0f);
    _image("lit_mask", viewport[2], viewport[3], 1, 1.0f);
    attack_send(SL_MSG_DONE, NULL, NULL, 0);
    attack_wait_for_grader();
    return SL_NOT_IMPLEMENTED;
}

ATTACK_LAB1_STUBS
