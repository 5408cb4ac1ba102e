#!/usr/bin/env bash
# handout_answers.sh SOLUTIONS_DIR TREE
# Does TREE (an unpacked student handout) hold an implementation of a lab
# step? For each lab, the calls that implement its steps, as patterns over the
# code with its comments taken out (as gcc -fpreprocessed does) and its white space
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


# The code files (C, C++, GLSL) of both trees, read as gcc -fpreprocessed -dD -E -P prints them,
# and the patterns (POSIX extended regular expressions, as grep -E reads them) matched, all in one
# python3: a gcc, sed and tr per file and two greps per pattern were most of the handout test's time.
exec python3 - "$solutions" "$tree" "${patterns[@]}" <<'PYTHON'
import fnmatch, os, re, sys, traceback

CODE = ('.c', '.h', '.cpp', '.glsl', '.vert', '.frag', '.geom')
# the directives gcc knows; any other (GLSL's #version) is an error to it, and the line is dropped
KNOWN = {'define', 'undef', 'include', 'include_next', 'import', 'if', 'ifdef', 'ifndef', 'elif',
         'elifdef', 'elifndef', 'else', 'endif', 'line', 'error', 'warning', 'pragma', 'ident',
         'sccs', 'assert', 'unassert'}
STRING = re.compile(r'"(?:[^"\\\n]|\\.)*"')
IDENT = r'[A-Za-z_][A-Za-z_0-9]*'
DIRECTIVE = re.compile(r'([ \t]*)#(?!#)[ \t]*([A-Za-z_0-9]*)(.*)', re.S)
DEFINE = re.compile(r'[ \t]*(' + IDENT + r')(\([^)]*\))?(.*)', re.S)
# in a macro's body: a literal (to the line's end if not closed) | a ## | a # (not of a ##) and what follows it
LITERAL = re.compile(r'"(?:[^"\\\n]|\\.)*"?|\'(?:[^\'\\\n]|\\.)*\'?')
PASTE = re.compile(r'(' + LITERAL.pattern + r')|(?:[ \t]*##)+|(?<!#)#(?!#)([ \t]*)(' + IDENT + ')?')
WHITE = re.compile(r'[ \t\n\r]+')


def uncomment(text):
    """The code without its comments, as gcc -fpreprocessed leaves it: a block comment becomes one
    space, a line comment ends before its newline (no line splicing), and a string or character
    literal, up to its closing quote or the line's end, is kept whole."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if c == '/' and text.startswith('/*', i):
            end = text.find('*/', i + 2)
            if end < 0:  # unterminated: gcc stops there
                break
            out.append(' ')
            i = end + 2
        elif c == '/' and text.startswith('//', i):
            end = text.find('\n', i)
            i = n if end < 0 else end
        elif c == '"' or c == "'":
            j = i + 1
            while j < n and text[j] != c and text[j] != '\n':
                j += 2 if text[j] == '\\' and j + 1 < n and text[j + 1] != '\n' else 1
            j = j + 1 if j < n and text[j] == c else j
            out.append(text[i:j])
            i = j
        else:
            j = i + 1
            while j < n and text[j] not in '/"\'':
                j += 1
            out.append(text[i:j])
            i = j
    return ''.join(out)


def define(rest):
    """REST of a #define line as gcc -dD prints it: the parameters without spaces, one space before
    the body, a space before each ##, none after a # that makes a string of a parameter. None where
    gcc finds the definition wrong (and prints nothing)."""
    d = DEFINE.match(rest)
    if not d:
        return None
    name, params, body = d.group(1), d.group(2), d.group(3).strip(' \t\r')
    names = None
    if params is None and d.group(3).startswith('('):  # a parameter list that does not end
        return None
    if params is not None:
        items = [p.strip(' \t') for p in params[1:-1].split(',')]
        items = [] if items == [''] else items
        if not all(re.fullmatch(IDENT, p) or (p == '...' and k == len(items) - 1) for k, p in enumerate(items)):
            return None
        names = set(items) | ({'__VA_ARGS__'} if '...' in items else set())
        name += '(' + ','.join(items) + ')'
    bare = LITERAL.sub('""', body)
    last = re.search(r'#+$', bare)  # ## at either end is wrong (a run of #s is read as ##s from its left)
    wrong = bare.startswith('##') or (last is not None and len(last.group()) % 2 == 0)

    def token(t):
        nonlocal wrong
        if t.group(1):  # a literal, as it is
            return t.group(1)
        if t.group(2) is None:
            return ' ##'
        if names is None:
            return t.group(0)
        if t.group(3) in names:
            return '#' + t.group(3)
        wrong = True
        return t.group(0)
    body = PASTE.sub(token, body)
    return None if wrong else '#define ' + name + (' ' + body if body else '')


def directives(code):
    """The lines of CODE with its directives as gcc -fpreprocessed -dD prints them."""
    lines = []
    for line in code.split('\n'):
        m = DIRECTIVE.match(line)
        if m:
            indented, name, rest = m.group(1), m.group(2), m.group(3)
            if name not in KNOWN:  # unknown (#version), a line marker (# 5 "f") or a null directive
                continue
            if indented or name not in ('define', 'undef', 'pragma'):  # gcc prints it as any other line
                pass
            elif name == 'pragma':
                if rest.split() == ['once']:  # gcc takes it, and prints nothing
                    continue
            elif name == 'define':
                line = define(rest)
                if line is None:
                    continue
            elif name == 'undef':
                line = '#undef ' + rest.strip(' \t\r')
        lines.append(line)
    return '\n'.join(lines)


def flatten(path):
    with open(path, 'rb') as f:
        text = f.read().decode('latin-1')
    code = directives(uncomment(text))
    # gcc -P prints nothing for the blank lines before the first code, and ends the last line
    code = re.sub(r'\A(?:[ \t\r]*\n)+', '', code)
    if code and not code.endswith('\n'):
        code += '\n'
    # (string literals emptied: a message that names the call to make is a hint, as a stub's comment is)
    code = STRING.sub('""', code)
    return WHITE.sub(' ', code).encode('latin-1')


def python_regex(ere):
    """A POSIX extended regular expression as Python's re reads it: the same but for bracket
    expressions, where POSIX takes a ']' first and every '[' and '\\' as they are."""
    out, i, n = [], 0, len(ere)
    while i < n:
        c = ere[i]
        if c == '\\':
            out.append(ere[i:i + 2])
            i += 2
        elif c == '[':
            j = i + 1
            negate = j < n and ere[j] == '^'
            j += negate
            items = []
            if j < n and ere[j] == ']':
                items.append('\\]')
                j += 1
            while j < n and ere[j] != ']':
                if ere[j] == '[' and j + 1 < n and ere[j + 1] in ':.=':
                    raise ValueError('a character class or collating element: ' + ere)
                items.append('\\' + ere[j] if ere[j] in '[\\' else ere[j])
                j += 1
            if j >= n:
                raise ValueError('a bracket expression that does not end: ' + ere)
            out.append('[' + ('^' if negate else '') + ''.join(items) + ']')
            i = j + 1
        else:
            out.append(c)
            i += 1
    return re.compile(''.join(out))


GLSL = ('*.glsl', '*.vert', '*.frag', '*.geom')


def code_files(tree):
    """Each code file of TREE (as find -type f finds them: no symbolic links): relative path, code
    flattened to one line (decoded as grep reads it in a UTF-8 locale)."""
    files = {}
    for root, dirs, names in os.walk(tree):
        for name in names:
            src = os.path.join(root, name)
            if name.endswith(CODE) and not os.path.islink(src) and os.path.isfile(src):
                files[os.path.relpath(src, tree)] = flatten(src).decode('utf-8', 'surrogateescape')
    return files


def matches(files, glob, regex):
    """The files (relative, in LC_ALL=C sort's order) of the ones GLOB names whose code matches."""
    globs = GLSL if glob == '*.glsl' else (glob,)
    return sorted((path for path, code in files.items()
                   if any(fnmatch.fnmatchcase(os.path.basename(path), g) for g in globs) and regex.search(code)),
                  key=os.fsencode)


def main(solutions, tree, patterns):
    """handout_answers SOLUTIONS TREE PATTERN...: a PATTERN is NAME|GLOB|REGEX"""
    solutions, tree = code_files(solutions), code_files(tree)
    status = 0
    for pattern in patterns:
        name, glob, regex = pattern.split('|', 2)
        regex = python_regex(regex)
        if not matches(solutions, glob, regex):
            sys.stdout.flush()
            print('handout_answers: the pattern for "%s" matches nothing in the solutions: it has rotted' % name,
                  file=sys.stderr, flush=True)
            status = 2
            continue
        for path in matches(tree, glob, regex):
            print('%s: %s' % (name, path))
            status = status or 1
    return status


try:
    sys.exit(main(sys.argv[1], sys.argv[2], sys.argv[3:]))
except Exception:  # the scan did not finish: as a rotted pattern, never as "found nothing"
    traceback.print_exc()
    sys.exit(2)
PYTHON
