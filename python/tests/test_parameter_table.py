"""The stubs of fair() against the parameter table (include/CGAL/Anisotropic_fairing/internal/parameter_table.h),
as the compiled part reads it: every keyword it takes is in __init__.pyi, in its order, optional, and the
words of those that take words are the stub's Literal. The stubs cannot be made from the table, so this
test names any keyword missing or mismatched."""
import ast
import os

from anisotropic_fairing import _core

STUBS = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'src', 'anisotropic_fairing', '__init__.pyi')
FIXED = ['attributes', 'vertex_is_constrained', 'callback', 'quiet']   # fair()'s own, not the table's


def stub_keywords():
    """{keyword: its annotation's AST} of fair() in __init__.pyi, in their order"""
    tree = ast.parse(open(STUBS, encoding='utf-8').read())
    fair = next(node for node in tree.body if isinstance(node, ast.FunctionDef) and node.name == 'fair')
    return {a.arg: a.annotation for a in fair.args.kwonlyargs}


def literal_words(annotation):
    """the values of the Literal inside Optional[Literal[...]] (None: no Literal)"""
    for node in ast.walk(annotation):
        if isinstance(node, ast.Subscript) and isinstance(node.value, ast.Name) and node.value.id == 'Literal':
            items = node.slice.elts if isinstance(node.slice, ast.Tuple) else [node.slice]
            return tuple(item.value for item in items)
    return None


def test_stubs_name_every_keyword_of_the_table_in_its_order():
    stubs = stub_keywords()
    names = list(_core.parameter_names)
    missing = [name for name in names if name not in stubs]
    extra = [name for name in stubs if name not in names and name not in FIXED]
    assert not missing, 'in the parameter table, not in %s: %s' % (STUBS, ', '.join(missing))
    assert not extra, 'in %s, not in the parameter table: %s' % (STUBS, ', '.join(extra))
    assert [name for name in stubs if name not in FIXED] == names, \
        'the stubs list the keywords in another order than the table'


def test_stubs_give_each_keyword_its_type_and_words():
    stubs = stub_keywords()
    for name in _core.parameter_names:
        annotation = ast.unparse(stubs[name])
        assert annotation.startswith('Optional['), '%s: the stub says %s, not Optional[...]' % (name, annotation)
        words = _core.parameter_words.get(name)
        if words is not None:
            assert literal_words(stubs[name]) == tuple(words), \
                '%s: the stub takes %s, the table %s' % (name, literal_words(stubs[name]), tuple(words))
