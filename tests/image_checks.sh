# Sourced by the tests that check pictures: check_image ARGS... runs `image_check ARGS`
# (its output, its exit status) in one image_check started by start_image_check IMAGE_CHECK
# (`image_check -`, a check a line): loading the image module costs more than a check.
start_image_check() {
  coproc image_checker { "$1" -; }
}
check_image() {
  local line IFS=$'\t'
  echo "$*" >&"${image_checker[1]}"
  while IFS= read -r line <&"${image_checker[0]}"; do
    [[ $line =~ ^image_check:\ exit\ ([0-9]+)$ ]] && return "${BASH_REMATCH[1]}"
    echo "$line"
  done
  echo "image_check stopped (checking $*)" >&2
  return 2
}
