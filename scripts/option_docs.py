#!/usr/bin/env python3
"""The options of the program anisotropic_fairing are described once: those of the library's parameters in the
parameter table (include/CGAL/Anisotropic_fairing/internal/parameter_table.h), the program's own in its option
table (tools/anisotropic_fairing/options.cpp); --help prints both, and the option list of the manual's page on
the program is made from it (the README points there).

    python3 scripts/option_docs.py TOOL            rewrite the page's list from TOOL --help
    python3 scripts/option_docs.py TOOL --check    exit 1 if it differs from TOOL --help (the test cli_option_docs)
"""
import difflib
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PAGE = os.path.join(ROOT, 'doc', 'Anisotropic_fairing', 'Command_line_program.txt')
PAGE_HEAD = '\\verbatim options\n'   # doxygen ignores the word after \verbatim; it marks the generated block
PAGE_END = '\\endverbatim'


def help_options(tool):
    """[(flag with its value, [help lines])] in the order of --help"""
    text = subprocess.run([tool, '--help'], capture_output=True, text=True, check=True).stdout
    block = text[text.index('\noptions:\n') + len('\noptions:\n'):text.index('\nOptions also accept')]
    options = []
    for line in block.splitlines():
        if line.startswith('  --'):
            name, _, rest = line[2:].partition('   ')
            options.append((name.strip(), [rest.strip()]))
        elif line.startswith(' ' * 28) and options:
            options[-1][1].append(line.strip())
        elif line.strip():
            sys.exit('option_docs.py: cannot read the help line %r' % line)
    return block, options


def replace_block(text, start, end, new):
    i = text.index(start)
    j = text.index(end, i + len(start))
    return text[:i] + new + text[j:], text[i:j]


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    tool, check_only = sys.argv[1], '--check' in sys.argv[2:]
    block, options = help_options(tool)
    if len(options) < 10:
        sys.exit('option_docs.py: --help lists %d options' % len(options))
    changed = []
    page = open(PAGE, encoding='utf-8').read()
    new_page, old = replace_block(page, PAGE_HEAD, PAGE_END, PAGE_HEAD + block + '\n')
    if new_page != page:
        changed.append((PAGE, old, PAGE_HEAD + block + '\n'))
    if check_only:
        for path, old, new in changed:
            sys.stdout.writelines(difflib.unified_diff(old.splitlines(True), new.splitlines(True), path, 'from --help'))
        if changed:
            sys.exit('option_docs.py: %s differs from the options of --help; run: python3 scripts/option_docs.py %s' %
                     (os.path.relpath(PAGE, ROOT), tool))
        print('the manual gives the options exactly as --help does (%d options)' % len(options))
        return
    open(PAGE, 'w', encoding='utf-8').write(new_page)
    print('wrote %d options into %s' % (len(options), os.path.relpath(PAGE, ROOT)))


if __name__ == '__main__':
    main()
