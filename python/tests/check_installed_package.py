#!/usr/bin/python3
"""The Python package as a user installs it (CTest: python_package).

    check_installed_package.py SOURCE_DIR VENV_DIR

In a fresh virtual environment with Debian's packages visible (--system-site-packages): `pip wheel .` and
`pip install .` from SOURCE_DIR, offline (--no-build-isolation --no-index); then, from a directory outside
the sources and without PYTHONPATH, `import anisotropic_fairing` gives the installed package, mypy's
stubtest finds its stubs (__init__.pyi, _core.pyi) true to it, mypy accepts python/example.py against
them, and the test suite (python/tests) passes on it. The test environment (AF_TOOL, AF_DATA, AF_TEST_DATA)
is passed on to the suite.
"""
import os
import shutil
import subprocess
import sys
import tempfile


def run(args, **kwargs):
    print('$', ' '.join(args), flush=True)
    subprocess.run(args, check=True, **kwargs)


def main():
    source, venv = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    shutil.rmtree(venv, ignore_errors=True)
    run(['/usr/bin/python3', '-m', 'venv', '--system-site-packages', venv])
    python = os.path.join(venv, 'bin', 'python')
    env = {k: v for k, v in os.environ.items() if k != 'PYTHONPATH'}
    env.setdefault('CMAKE_BUILD_PARALLEL_LEVEL', '2')
    offline = ['--no-build-isolation', '--no-index', '--disable-pip-version-check']
    with tempfile.TemporaryDirectory() as elsewhere:
        run([python, '-m', 'pip', 'wheel', *offline, '--no-deps', '-w', os.path.join(elsewhere, 'wheels'), source],
            env=env)
        wheels = os.listdir(os.path.join(elsewhere, 'wheels'))
        assert len(wheels) == 1 and wheels[0].startswith('anisotropic_fairing-'), wheels
        run([python, '-m', 'pip', 'install', *offline, source], env=env)
        show = 'import anisotropic_fairing as af; print(af.__file__); print(af.__version__)'
        found = subprocess.run([python, '-c', show],
                               cwd=elsewhere, env=env, check=True, capture_output=True, text=True).stdout.split()
        assert found[0].startswith(venv + os.sep), 'imported %s, not the package installed in %s' % (found[0], venv)
        print('installed:', found[0], found[1])
        config = os.path.join(source, 'python', 'tests', 'mypy.ini')
        run([python, '-m', 'mypy.stubtest', '--mypy-config-file', config, '--allowlist',
             os.path.join(source, 'python', 'tests', 'stubtest_allowlist.txt'), 'anisotropic_fairing'],
            cwd=elsewhere, env=env)
        run([python, '-m', 'mypy', '--config-file', config, '--no-incremental',
             os.path.join(source, 'python', 'example.py')],
            cwd=elsewhere, env=env)
        run([python, '-m', 'pytest', '-q', '-p', 'no:cacheprovider', os.path.join(source, 'python', 'tests')],
            cwd=elsewhere, env=env)


if __name__ == '__main__':
    main()
