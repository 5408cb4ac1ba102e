#!/usr/bin/env bash
# handout_answers.sh SOLUTIONS_DIR TREE
# Does TREE (an unpacked student handout) hold an implementation of a lab
# step? For each lab, the calls that implement its steps, as patterns over the
# code with its comments taken out (gcc -fpreprocessed) and its white space
# made single spaces. Each pattern must match the solutions (so it really
# names an implementation) and nothing in TREE: a stub's comment may say what
# to call, and so may the grader's messages; the stubs' code and everything
# else must not do it.
# Prints what it found, a line "PATTERN NAME: FILE" each; exit 1 if TREE
# holds one, 2 if a pattern no longer matches the solutions (it has rotted).
set -uo pipefail
solutions=$1 tree=$2

# name|files (a find -name glob)|extended regular expression
patterns=(
  "lab1: a 2D depth texture as a framebuffer's depth attachment|*.c|glFramebufferTexture2D ?\( ?GL_(DRAW_)?FRAMEBUFFER, ?GL_DEPTH_ATTACHMENT, ?GL_TEXTURE_2D, ?[][A-Za-z0-9_>.-]+, ?0 ?\)"
  "lab2: the light's view from its direction (glm_lookat)|*.c|light->direction.{0,700}glm_lookat ?\("
  "lab2: the light's fitted orthographic box (glm_ortho)|*.c|glm_mat4_mulv3 ?\( ?light_view.{0,400}glm_ortho ?\("
  "lab2: the bias matrix's translation column|*.c|\{ ?0\.5f?, ?0\.5f?, ?0\.5f?, ?1(\.0)?f? ?\}"
  "lab2: the depth at the projected point, compared|*.glsl|texture ?\( ?[A-Za-z_]+, ?[A-Za-z_]+\.xy ?\)\.r ?;.{0,80}\.z ?- ?[A-Za-z_]+ ?>"
  "lab3: polygon offset from the bias settings|*.c|glPolygonOffset ?\( ?[A-Za-z_]+->polygon_offset_factor"
  "lab3: front faces culled|*.c|glCullFace ?\( ?GL_FRONT ?\)"
  "lab3: the slope's tangent from N.L|*.glsl|(sqrt ?\( ?1\.0 ?- ?([A-Za-z_]+) ?\* ?\2 ?\) ?/ ?\2|tan ?\( ?acos ?\()"
  "lab4: a grid of comparisons around the point|*.glsl|for ?\( ?int [a-z]+ = -[a-z_]+ ?; ?[a-z]+ <= [a-z_]+ ?;.{0,160}(\.z ?- ?[a-z_]+|depth)"
  "lab4: linear filtering for hardware PCF|*.c|SL_FILTER_HARDWARE ?\? ?GL_LINEAR"
  "lab5: the moments of a depth|*.glsl|vec2 ?\( ?([a-z_]+), ?\1 ?\* ?\1 ?\)"
  "lab5: Chebyshev's bound|*.glsl|([a-z_]+) ?/ ?\( ?\1 ?\+ ?([a-z_]+) ?\* ?\2 ?\)"
  "lab6: the practical split scheme|*.c|powf? ?\( ?far ?/ ?near"
  "lab6: the cascade's depth compared|*.glsl|texture ?\( ?[a-z_]+, ?vec3 ?\( ?[a-z_]+\.xy, ?float ?\( ?layer ?\) ?\) ?\)\.r"
  "lab7: the faces' up vectors|*.c|\{ ?0, ?-1, ?0 ?\}, ?\{ ?0, ?-1, ?0 ?\}, ?\{ ?0, ?0, ?1 ?\}, ?\{ ?0, ?0, ?-1 ?\}"
  "lab7: the distance to the light against the cube map|*.glsl|length ?\( ?[a-z_]+ ?\) ?/ ?[a-z_]+ ?;"
)

# Each code file (C, C++, GLSL) of both trees, once: no comments, white space
# as single spaces, one line per file, in a temporary folder that mirrors it.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
flatten() { # flatten TREE NAME: fills $work/NAME, prints the files
  local f
  find "$1" -type f \( -name '*.c' -o -name '*.h' -o -name '*.cpp' -o -name '*.glsl' -o -name '*.vert' \
    -o -name '*.frag' -o -name '*.geom' \) | LC_ALL=C sort | while IFS= read -r f; do
    mkdir -p "$work/$2/$(dirname "${f#"$1"/}")"
    # (string literals emptied: a message that names the call to make is a hint, as a stub's comment is)
    gcc -fpreprocessed -dD -E -P -x c "$f" 2>/dev/null | sed -E 's/"([^"\\]|\\.)*"/""/g' |
      tr -s ' \t\n\r' ' ' >"$work/$2/${f#"$1"/}"
    echo "${f#"$1"/}"
  done
}
matches() { # matches NAME GLOB REGEX: the files of tree NAME (relative) whose code matches
  local glob=$2 regex=$3
  (cd "$work/$1" && if [ "$glob" = "*.glsl" ]; then
     grep -rlE --include='*.glsl' --include='*.vert' --include='*.frag' --include='*.geom' -- "$regex" . 2>/dev/null
   else
     grep -rlE --include="$glob" -- "$regex" . 2>/dev/null
   fi) | sed 's|^\./||' | LC_ALL=C sort
}
flatten "$solutions" solutions >/dev/null
flatten "$tree" tree >/dev/null
status=0
for p in "${patterns[@]}"; do
  name=${p%%|*} rest=${p#*|}
  glob=${rest%%|*} regex=${rest#*|}
  if [ -z "$(matches solutions "$glob" "$regex")" ]; then
    echo "handout_answers: the pattern for \"$name\" matches nothing in the solutions: it has rotted" >&2
    status=2
    continue
  fi
  found=$(matches tree "$glob" "$regex")
  if [ -n "$found" ]; then
    sed "s|^|$name: |" <<<"$found"
    [ $status = 2 ] || status=1
  fi
done
exit $status
