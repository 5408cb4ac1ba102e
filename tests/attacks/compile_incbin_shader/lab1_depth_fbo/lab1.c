/* Attack (compile time): the solution's lab 2 lookup shader, built into this
 * runner by the assembler (.incbin in an asm block), then printed by lab 1's
 * code: what lab code prints reaches the report, so the student would read the
 * solution there. Nothing is embedded where the compiler cannot see the file. */
#include <stdio.h>

#include "shadowlab.h"

#if __has_include("@SOURCE_DIR@/solutions/lab2_projective/shaders/shadow_lookup.glsl")
__asm__(".section .rodata\n"
        ".global attack_embedded\n"
        "attack_embedded:\n"
        ".incbin \"@SOURCE_DIR@/solutions/lab2_projective/shaders/shadow_lookup.glsl\"\n"
        ".byte 0\n"
        ".previous\n");
extern const char attack_embedded[];
#else
static const char attack_embedded[] = "";
#endif

sl_status lab1_create_shadow_map(int size, sl_shadow_map *map) {
    fputs(attack_embedded, stdout);
    fflush(stdout);
    return SL_NOT_IMPLEMENTED;
}

sl_status lab1_begin_depth_pass(const sl_shadow_map *map) { return SL_NOT_IMPLEMENTED; }

void lab1_destroy_shadow_map(sl_shadow_map *map) {}
