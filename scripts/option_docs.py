#!/usr/bin/env python3
"""The options of the program anisotropic_fairing are described once, in its option table (the text of
--help); the README's option table and the manual's page on the program are made from it.

    python3 scripts/option_docs.py TOOL            rewrite both from TOOL --help
    python3 scripts/option_docs.py TOOL --check    exit 1 if either differs from TOOL --help (the test cli_option_docs)
"""
import difflib
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
README = os.path.join(ROOT, 'README.md')
PAGE = os.path.join(ROOT, 'doc', 'Anisotropic_fairing', 'Command_line_program.txt')
README_HEAD = '| option | meaning |\n|---|---|\n'
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


def readme_table(options):
    def cell(s):
        return s.replace('|', '\\|')
    rows = ['| `%s` | %s |' % (cell(name), cell(' '.join(lines))) for name, lines in options]
    return README_HEAD + '\n'.join(rows) + '\n'


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
    readme = open(README, encoding='utf-8').read()
    new_readme, old = replace_block(readme, README_HEAD, '\n\n', readme_table(options).rstrip('\n'))
    if new_readme != readme:
        changed.append((README, old, readme_table(options).rstrip('\n')))
    page = open(PAGE, encoding='utf-8').read()
    new_page, old = replace_block(page, PAGE_HEAD, PAGE_END, PAGE_HEAD + block + '\n')
    if new_page != page:
        changed.append((PAGE, old, PAGE_HEAD + block + '\n'))
    if check_only:
        for path, old, new in changed:
            sys.stdout.writelines(difflib.unified_diff(old.splitlines(True), new.splitlines(True), path, 'from --help'))
        if changed:
            sys.exit('option_docs.py: %s differ from the options of --help; run: python3 scripts/option_docs.py %s' %
                     (' and '.join(os.path.relpath(p, ROOT) for p, _, _ in changed), tool))
        print('the README and the manual give the options exactly as --help does (%d options)' % len(options))
        return
    open(README, 'w', encoding='utf-8').write(new_readme)
    open(PAGE, 'w', encoding='utf-8').write(new_page)
    print('wrote %d options into %s and %s' % (len(options), os.path.relpath(README, ROOT), os.path.relpath(PAGE, ROOT)))


if __name__ == '__main__':
    main()
