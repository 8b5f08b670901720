#!/usr/bin/env python3
"""Checks the shape of the code in include/, tools/, python/ and distributed/ (C++ and Python sources):
no line over 120 characters, no file over 600 lines, no function over 80 lines (tables aside: the lines of a
brace-initialised array or an X-macro list inside a function are not counted), and no `default:` in a
`to_string` switch, so that a new enumerator gives a -Wswitch warning instead of compiling silently.

    python3 scripts/check_code_shape.py [ROOT]

Prints each offender as file:line and exits 1 if there is any. C++ functions are found by brace matching
from the signature line, on the text with comments, string literals and preprocessor lines blanked out."""
import ast, os, re, sys

FOLDERS = ['include', 'tools', 'python', 'distributed']
CPP = ('.h', '.hpp', '.ipp', '.cpp', '.cc', '.cxx')
PY = ('.py', '.pyi')
MAX_LINE, MAX_FILE, MAX_FUNCTION = 120, 600, 80


def blank_cpp(text):
    """The text with comments, string and character literals and preprocessor lines replaced by spaces,
    newlines kept, so that braces are code and line numbers stay right."""
    out, i, n = [], 0, len(text)
    line_start = True
    while i < n:
        c = text[i]
        if line_start and c == '#':          # a directive, with its continuation lines
            j = i
            while j < n and not (text[j] == '\n' and text[j - 1] != '\\'):
                j += 1
            out.append(re.sub(r'[^\n]', ' ', text[i:j]))
            i = j
            continue
        if c == '\n':
            line_start = True
        elif not c.isspace():
            line_start = False
        if text.startswith('//', i):
            j = text.find('\n', i)
            j = n if j < 0 else j
            out.append(' ' * (j - i)); i = j
        elif text.startswith('/*', i):
            j = text.find('*/', i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r'[^\n]', ' ', text[i:j])); i = j
        elif c == 'R' and i + 1 < n and text[i + 1] == '"' and not (i and (text[i - 1].isalnum() or text[i - 1] == '_')):
            m = re.match(r'R"([^(\s]*)\(', text[i:])
            end = text.find(')' + m.group(1) + '"', i) if m else -1
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append('""' + re.sub(r'[^\n]', ' ', text[i + 2:j])); i = j
        elif c == '"' or (c == "'" and not (i and text[i - 1].isalnum())):   # 1'000 is a number
            j = i + 1
            while j < n and text[j] != c and text[j] != '\n':
                j += 2 if text[j] == '\\' else 1
            j = min(j + 1, n)
            out.append(c + ' ' * (j - i - 2) + c if j - i >= 2 else text[i:j]); i = j
        else:
            out.append(c); i += 1
    return ''.join(out)


CONTROL = re.compile(r'^\s*(if|for|while|switch|catch|do|else|try)\b')
LABEL = re.compile(r'^\s*(public|private|protected)\s*:(?!:)')
QUALIFIERS = r'(\s*(const|volatile|noexcept(\s*\([^()]*\))?|override|final|mutable|&&|&))*'
FUNCTION_END = re.compile(r'\)' + QUALIFIERS + r'(\s*->\s*[\w:<>,\s*&\[\]]+)?\s*$')
CTOR_INIT = re.compile(r'\)' + QUALIFIERS + r'\s*:(?!:)')


def skip_template(head):
    m = re.match(r'\s*template\s*<', head)
    if not m:
        return head
    depth, i = 1, m.end()
    while i < len(head) and depth:
        depth += {'<': 1, '>': -1}.get(head[i], 0)
        i += 1
    return skip_template(head[i:])


def function_name(head):
    head = skip_template(head)
    m = re.search(r'(operator\s*\(\s*\)|operator\s*[^\s\w(]+|~?[A-Za-z_][\w:~]*)\s*\(', head)
    return m.group(1).strip() if m else '?'


def cpp_functions(text):
    """(name, first line, last line, table lines, body text) of each outermost function in C++ source."""
    code = blank_cpp(text)
    line_of = [0] * (len(code) + 1)
    line = 1
    for i, c in enumerate(code):
        line_of[i] = line
        if c == '\n':
            line += 1
    line_of[len(code)] = line
    found = []
    stack = []               # 'scope', 'init', 'table' outside functions
    head_start = 0
    i, n = 0, len(code)
    while i < n:
        c = code[i]
        if c == ';':
            head_start = i + 1
        elif c == '}':
            kind = stack.pop() if stack else 'scope'
            if kind != 'init':
                head_start = i + 1
        elif c == '{':
            head = code[head_start:i]
            head = LABEL.sub('', head)
            stripped = head.strip()
            constructor = CTOR_INIT.search(stripped) and not CONTROL.match(stripped)
            if constructor and re.search(r'[\w>]$', stripped):   # a member initialised with braces
                stack.append('init')
            elif stripped and (FUNCTION_END.search(stripped) or constructor and stripped.endswith('}')) \
                    and not CONTROL.match(stripped):
                j, depth, tables = i, 0, 0
                table_depth, table_open = None, None
                inner_start = i + 1
                while j < n:
                    if code[j] == '{':
                        if table_depth is None:
                            inner = code[inner_start:j].rstrip()
                            if re.search(r'(=|\])$', inner):
                                table_depth, table_open = depth, line_of[j]
                        depth += 1
                    elif code[j] == '}':
                        depth -= 1
                        if table_depth is not None and depth == table_depth:
                            tables += line_of[j] - table_open
                            table_depth = None
                        if depth == 0:
                            break
                    if code[j] in ';{}':
                        inner_start = j + 1
                    j += 1
                first = head_start + len(code[head_start:i]) - len(code[head_start:i].lstrip())
                lstrip_label = LABEL.match(code[head_start:i])
                if lstrip_label:
                    rest = code[head_start + lstrip_label.end():i]
                    first = head_start + lstrip_label.end() + len(rest) - len(rest.lstrip())
                tables += x_macro_lines(text, line_of[i], line_of[min(j, n - 1)])
                found.append((function_name(stripped), line_of[first], line_of[min(j, n - 1)], tables,
                              code[i:j + 1]))
                i = j + 1
                head_start = i
                continue
            elif re.search(r'(=|\])$', stripped):
                stack.append('table')
            else:
                stack.append('scope')
            if stack[-1] != 'init':
                head_start = i + 1
        i += 1
    return found


def x_macro_lines(text, first, last):
    """Lines of runs of three or more X-macro rows (an upper-case macro called alone on its line)."""
    lines = text.split('\n')[first - 1:last]
    row = re.compile(r'^\s*[A-Z][A-Z0-9_]*\s*\(.*\)\s*\\?\s*$')
    count, run = 0, 0
    for text_line in lines + ['']:
        if row.match(text_line):
            run += 1
        else:
            if run >= 3:
                count += run
            run = 0
    return count


def python_functions(text):
    tree = ast.parse(text)
    for node in ast.walk(tree):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            tables = 0
            for inner in ast.walk(node):
                if isinstance(inner, (ast.Assign, ast.AnnAssign, ast.Return)) and \
                        isinstance(inner.value, (ast.List, ast.Dict, ast.Tuple, ast.Set)):
                    tables += inner.value.end_lineno - inner.value.lineno
            yield node.name, node.lineno, node.end_lineno, tables


def check_file(path, shown, offenders):
    with open(path, encoding='utf-8', errors='replace') as f:
        text = f.read()
    lines = text.split('\n')
    if lines and lines[-1] == '':
        lines.pop()
    if len(lines) > MAX_FILE:
        offenders.append('%s:1: file of %d lines (at most %d)' % (shown, len(lines), MAX_FILE))
    for number, line in enumerate(lines, 1):
        if len(line) > MAX_LINE:
            offenders.append('%s:%d: line of %d characters (at most %d)' % (shown, number, len(line), MAX_LINE))
    if path.endswith(PY):
        try:
            functions = list(python_functions(text))
        except SyntaxError as error:
            offenders.append('%s:%s: cannot parse: %s' % (shown, error.lineno, error.msg))
            return
        bodies = [(name, first, last, tables, '') for name, first, last, tables in functions]
    else:
        bodies = cpp_functions(text)
    for name, first, last, tables, body in bodies:
        length = last - first + 1 - tables
        if length > MAX_FUNCTION:
            offenders.append('%s:%d: function %s of %d lines (at most %d%s)'
                             % (shown, first, name, length, MAX_FUNCTION,
                                ', tables aside' if tables else ''))
        if name.split('::')[-1] == 'to_string' and re.search(r'\bdefault\s*:', body):
            at = first + body[:re.search(r'\bdefault\s*:', body).start()].count('\n')
            offenders.append('%s:%d: `default:` in to_string, where -Wswitch should flag a new enumerator'
                             % (shown, at))


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), '..'))
    offenders = []
    for folder in FOLDERS:
        for directory, subdirectories, files in os.walk(os.path.join(root, folder)):
            subdirectories[:] = sorted(d for d in subdirectories if not d.startswith('.') and d != '__pycache__')
            for name in sorted(files):
                if name.endswith(CPP + PY):
                    path = os.path.join(directory, name)
                    check_file(path, os.path.relpath(path, root), offenders)
    print('\n'.join(offenders) if offenders else
          'no line over %d characters, file over %d lines, function over %d lines or default: in to_string'
          % (MAX_LINE, MAX_FILE, MAX_FUNCTION))
    sys.exit(1 if offenders else 0)


if __name__ == '__main__':
    main()
