"""A strict reader of MuJoCo's ``mjcf.schema`` grammar syntax into the typed IR.

Two phases. A recursive-descent parser turns the text into raw declarations that remember
their line numbers; a resolver then splices ``use``d groups, checks every cross reference
(children, groups, enums, namespaces, constraint names, defaults) and builds ``ir.Schema``.
Every problem is a :class:`GrammarError` reading ``path:line: message``.
"""

from __future__ import annotations

import copy
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Literal

from codegen import ir, naming


class GrammarError(ValueError):
    """A malformed grammar; ``str()`` is ``path:line: message``."""

    def __init__(self, path: str, line: int, message: str) -> None:
        super().__init__(f"{path}:{line}: {message}")
        self.path = path
        self.line = line
        self.message = message


def parse_grammar(
    text: str, path: str = "<string>", constants: Mapping[str, int] | None = None
) -> ir.Schema:
    """Read ``mjcf.schema`` text; ``constants`` resolve symbolic arity bounds like ``mjNREF``."""
    declarations = _Parser(text, path, constants or {}).parse()
    return _Resolver(declarations, path).resolve()


# --------------------------------------------------------------------------------- lexer

# A number never swallows the first dot of a range: ``1..3`` is NUMBER DOTDOT NUMBER.
_TOKEN_RE = re.compile(
    r"""
      (?P<space>[ \t\r]+)
    | (?P<comment>\#[^\n]*)
    | (?P<newline>\n)
    | (?P<string>"[^"\n]*")
    | (?P<number>-?(?:\d+(?:\.(?!\.)\d*)?|\.\d+)(?:[eE][+-]?\d+)?)
    | (?P<dotdot>\.\.)
    | (?P<ident>[A-Za-z_][A-Za-z0-9_]*)
    | (?P<punct>[{}()\[\]<>:=,?!*+])
    """,
    re.VERBOSE,
)
_INT_RE = re.compile(r"-?\d+")


@dataclass(frozen=True)
class _Token:
    kind: str  # "ident", "number", "string", "dotdot", "eof", or the punctuation character
    text: str  # strings without their quotes
    line: int

    def show(self) -> str:
        return "end of file" if self.kind == "eof" else repr(self.text)


def _lex(text: str, path: str) -> tuple[list[_Token], dict[int, str]]:
    """Tokens, and the comment of each line (a trailing comment is a doc string)."""
    tokens: list[_Token] = []
    comments: dict[int, str] = {}
    line, pos = 1, 0
    while pos < len(text):
        match = _TOKEN_RE.match(text, pos)
        if match is None:
            problem = "unterminated string" if text[pos] == '"' else (
                f"unexpected character {text[pos]!r}")
            raise GrammarError(path, line, problem)
        kind, value = match.lastgroup or "", match.group()
        if kind == "newline":
            line += 1
        elif kind == "comment":
            comments[line] = value[1:].strip()
        elif kind == "string":
            tokens.append(_Token("string", value[1:-1], line))
        elif kind == "punct":
            tokens.append(_Token(value, value, line))
        elif kind != "space":
            tokens.append(_Token(kind, value, line))
        pos = match.end()
    tokens.append(_Token("eof", "", line))
    return tokens, comments


# ------------------------------------------------------------------- raw declarations


@dataclass
class _Default:
    text: str  # the MJCF text: "3", "hinge", "0 0 1"
    form: Literal["number", "ident", "string", "list"]
    numbers: list[str]  # the number tokens of a "number" or "list" default


@dataclass
class _Attr:
    attr: ir.AttributeDef
    line: int
    default: _Default | None


@dataclass
class _Use:
    group: str
    line: int


@dataclass
class _Child:
    element: str
    card: ir.Cardinality
    line: int


@dataclass
class _Constraint:
    constraint: ir.ConstraintDef
    line: int


_Member = _Attr | _Use | _Child | _Constraint


@dataclass
class _Group:
    name: str
    variant: bool
    members: list[_Member]
    line: int


@dataclass
class _Element:
    name: str
    tag: str
    struct: str | None
    alias: str | None
    members: list[_Member]
    line: int
    doc: str


@dataclass
class _Enum:
    enum: ir.EnumDef
    line: int


@dataclass
class _Declarations:
    enums: dict[str, _Enum] = field(default_factory=dict[str, _Enum])
    groups: dict[str, _Group] = field(default_factory=dict[str, _Group])
    elements: dict[str, _Element] = field(default_factory=dict[str, _Element])


@dataclass(frozen=True)
class _Type:
    kind: ir.AttrKind
    dtype: ir.DType | None = None
    arity: tuple[int, int | None] | None = None
    target: str | None = None  # enum name (keyword, flags) or namespace (id, ref)


# ------------------------------------------------------------------------------ parser

_NUMERIC_TYPES: dict[str, tuple[ir.AttrKind, ir.DType]] = {
    "double": ("real", "double"), "float": ("real", "float"), "int": ("int", "int"),
}
_TEXT_TYPES: dict[str, ir.AttrKind] = {
    "bool": "bool", "string": "string", "file": "file", "chars": "chars",
}
_TARGET_TYPES: dict[str, ir.AttrKind] = {
    "enum": "keyword", "flags": "flags", "id": "id", "ref": "ref",
}
_CARDINALITIES: dict[str, ir.Cardinality] = {"?": "?", "!": "!", "*": "*", "R": "R"}
_CONSTRAINT_KINDS: dict[str, ir.ConstraintKind] = {
    "exclusive": "exclusive", "together": "together", "requires": "requires", "oneof": "oneof",
}
_DECLARATION_KEYWORDS = frozenset({"enum", "group", "element"})

# Facet name -> token kinds its value may take; an empty set marks a flag without a value.
_FLAG: frozenset[str] = frozenset()
_NAME = frozenset({"ident"})
_ANY_VALUE = frozenset({"ident", "string", "number"})
_ATTRIBUTE_FACETS: dict[str, frozenset[str]] = {
    "required": _FLAG, "nodefault": _FLAG, "positive": _FLAG,
    "pattern": frozenset({"string"}), "field": _NAME,
    "min": frozenset({"number"}), "max": frozenset({"number"}),
    "dim": _ANY_VALUE, "reading": _NAME, "writing": _NAME,
}
# ``field`` on an element names the sub-struct of mjVisual its attributes live in.
_ELEMENT_FACETS: dict[str, frozenset[str]] = {
    "xml": _NAME, "alias": _NAME, "field": _NAME, "control": _ANY_VALUE, "output": _ANY_VALUE,
}
_VALUE_NAMES = {"ident": "a name", "string": "a quoted string", "number": "a number"}


class _Parser:
    """Recursive descent over the token stream; members are one per line."""

    def __init__(self, text: str, path: str, constants: Mapping[str, int]) -> None:
        self._path = path
        self._tokens, self._comments = _lex(text, path)
        self._pos = 0
        self._constants = constants
        self._last_line = 1  # line of the token consumed last ...
        self._line_before = 1  # ... and of the one before it

    # -- token helpers

    def _error(self, line: int, message: str) -> GrammarError:
        return GrammarError(self._path, line, message)

    def _peek(self, ahead: int = 0) -> _Token:
        return self._tokens[min(self._pos + ahead, len(self._tokens) - 1)]

    def _next(self) -> _Token:
        token = self._peek()
        self._pos = min(self._pos + 1, len(self._tokens) - 1)
        self._line_before, self._last_line = self._last_line, token.line
        return token

    def _unexpected(self, token: _Token, expected: str) -> GrammarError:
        """``token`` (just consumed) is not what continues the line: blame the right line."""
        if token.line > self._line_before:
            return self._error(self._line_before, f"expected {expected} at the end of the line")
        return self._error(token.line, f"expected {expected}, got {token.show()}")

    def _accept(self, kind: str) -> bool:
        if self._peek().kind == kind:
            self._next()
            return True
        return False

    def _expect(self, kind: str, what: str) -> _Token:
        token = self._next()
        if token.kind != kind:
            raise self._unexpected(token, what)
        return token

    def _ident(self, what: str) -> _Token:
        return self._expect("ident", what)

    def _end_of_line(self, line: int, what: str) -> None:
        """Members are line-oriented: nothing but a closing brace may follow on the line."""
        token = self._peek()
        if token.line == line and token.kind not in ("}", "eof"):
            raise self._error(line, f"unexpected {token.show()} after {what}")

    # -- declarations

    def parse(self) -> _Declarations:
        decls = _Declarations()
        while self._peek().kind != "eof":
            token = self._next()
            keyword = token.text if token.kind == "ident" else ""
            if keyword == "enum":
                enum = self._enum(token)
                self._check_new(decls.enums, enum.enum.name, "enum", token.line)
                decls.enums[enum.enum.name] = enum
            elif keyword == "group":
                group = self._group(token)
                self._check_new(decls.groups, group.name, "group", token.line)
                decls.groups[group.name] = group
            elif keyword == "element":
                element = self._element(token)
                self._check_new(decls.elements, element.name, "element", token.line)
                decls.elements[element.name] = element
            else:
                raise self._error(
                    token.line, f"expected 'enum', 'group' or 'element', got {token.show()}")
        return decls

    def _check_new(
        self, table: Mapping[str, _Enum | _Group | _Element], name: str, what: str, line: int
    ) -> None:
        first = table.get(name)
        if first is not None:
            raise self._error(
                line, f"duplicate {what} {name!r} (first declared on line {first.line})")

    def _enum(self, start: _Token) -> _Enum:
        name = self._ident("enum name").text
        ctype = self._ident("C enum type after ':'").text if self._accept(":") else None
        self._expect("{", f"'{{' to open enum {name!r}")
        values: list[tuple[str, str]] = []
        while not self._accept("}"):
            self._check_open("enum", name, start)
            key, value, line = self._enum_value()
            if any(key == k for k, _ in values):
                raise self._error(line, f"duplicate keyword {key!r} in enum {name!r}")
            values.append((key, value))
            self._end_of_line(line, f"keyword {key!r}")
        if not values:
            raise self._error(start.line, f"enum {name!r} is empty")
        doc = self._comments.get(start.line, "")
        return _Enum(ir.EnumDef(name, values, ctype, doc), start.line)

    def _enum_value(self) -> tuple[str, str, int]:
        key = self._next()
        if key.kind not in ("ident", "string") or not key.text or key.text.split() != [key.text]:
            raise self._error(key.line, f"expected an enum keyword, got {key.show()} (quote "
                                        'keywords that are not names, like "2d")')
        self._expect("=", f"'=' after keyword {key.text!r}")
        value = self._next()
        if value.kind != "ident" and not (value.kind == "number" and _INT_RE.fullmatch(value.text)):
            raise self._unexpected(value, f"a C constant or an integer for keyword {key.text!r}")
        return key.text, value.text, key.line

    def _group(self, start: _Token) -> _Group:
        name = self._ident("group name").text
        variant = self._peek().kind == "ident" and self._peek().text == "variant"
        if variant:
            self._next()
        members = self._block("group", name, start)
        if not members:
            raise self._error(start.line, f"group {name!r} is empty")
        return _Group(name, variant, members, start.line)

    def _element(self, start: _Token) -> _Element:
        name = self._ident("element name").text
        struct = self._ident("struct name after ':'").text if self._accept(":") else None
        facets = self._facets(_ELEMENT_FACETS, f"element {name!r}") if self._accept("(") else {}
        xml, alias = facets.get("xml"), facets.get("alias")
        doc = self._comments.get(start.line, "")
        members = self._block("element", name, start)
        tag = xml.text if xml is not None else name
        return _Element(name, tag, struct, alias.text if alias else None, members, start.line,
                        doc)

    def _block(self, what: str, name: str, start: _Token) -> list[_Member]:
        self._expect("{", f"'{{' to open {what} {name!r}")
        members: list[_Member] = []
        while not self._accept("}"):
            self._check_open(what, name, start)
            first = self._peek()
            member = self._member(what)
            if member is not None:
                members.append(member)
            self._end_of_line(first.line, f"the {what} member on this line")
        return members

    def _check_open(self, what: str, name: str, start: _Token) -> None:
        """A block ends with '}': report end of file or a new declaration at the opening line."""
        token, after = self._peek(), self._peek(1)
        if token.kind == "eof":
            where = "end of file"
        elif (token.kind == "ident" and token.text in _DECLARATION_KEYWORDS
              and after.kind == "ident" and after.line == token.line):
            where = f"line {token.line}"
        else:
            return
        raise self._error(start.line, f"unterminated {what} {name!r}: missing '}}' before {where}")

    # -- members

    def _member(self, owner: str) -> _Member | None:
        token = self._next()  # starts a line, so _unexpected's end-of-line blame is wrong here
        if token.kind != "ident":
            raise self._error(token.line, "expected an attribute, 'child', 'use', 'set' or a "
                                          f"constraint, got {token.show()}")
        if self._peek().kind == ":":  # any word can name an attribute, even 'child'
            return self._attribute(token)
        if token.text == "use":
            return _Use(self._ident("group name after 'use'").text, token.line)
        if token.text in ("child", "set") and owner == "group":
            raise self._error(token.line, f"'{token.text}' is not allowed in a group")
        if token.text == "child":
            return self._child(token)
        if token.text == "set":
            self._set()
            return None
        if token.text in _CONSTRAINT_KINDS:
            return self._constraint(token)
        raise self._error(token.line, f"unknown keyword {token.text!r}: expected 'name : type', "
                                      "'child', 'use', 'set' or a constraint")

    def _child(self, start: _Token) -> _Child:
        name = self._ident("element name after 'child'").text
        card = self._next()
        if card.line != start.line:
            raise self._error(start.line, f"missing cardinality of child {name!r}: "
                                          "expected one of ? ! * R")
        value = _CARDINALITIES.get(card.text) if card.kind != "string" else None
        if value is None:
            raise self._error(start.line, f"bad cardinality {card.show()} of child {name!r}: "
                                          "expected one of ? ! * R")
        return _Child(name, value, start.line)

    def _set(self) -> None:
        """``set field = CONST``: what the element's identity implies in C; not modelled."""
        field_name = self._ident("struct field after 'set'").text
        self._expect("=", f"'=' after 'set {field_name}'")
        value = self._next()
        if value.kind not in ("ident", "number"):
            raise self._unexpected(value, f"a C constant for 'set {field_name}'")

    def _constraint(self, verb: _Token) -> _Constraint:
        bundles: list[list[str]] = []
        while self._peek().kind == "ident" and self._peek().line == verb.line:
            bundle = [self._next().text]
            while self._accept("+"):
                bundle.append(self._ident(f"attribute name after '+' in '{verb.text}'").text)
            bundles.append(bundle)
        names = [n for b in bundles for n in b]
        if len(bundles) < 2:
            raise self._error(verb.line, f"'{verb.text}' needs at least two attribute bundles")
        if verb.text == "requires" and (len(bundles) != 2 or len(names) != 2):
            raise self._error(verb.line, "'requires' takes exactly two attributes")
        repeated = sorted({n for n in names if names.count(n) > 1})
        if repeated:
            raise self._error(verb.line, f"'{verb.text}' names {repeated[0]!r} twice")
        return _Constraint(ir.ConstraintDef(_CONSTRAINT_KINDS[verb.text], bundles), verb.line)

    # -- attributes

    def _attribute(self, name: _Token) -> _Attr:
        self._expect(":", f"':' after attribute {name.text!r}")
        typ = self._type(name.text)
        default = self._default(name.text) if self._accept("=") else None
        attr = ir.AttributeDef(
            name=name.text, py_name=naming.py_name(name.text), kind=typ.kind, dtype=typ.dtype,
            arity=typ.arity,
            enum=typ.target if typ.kind in ("keyword", "flags") else None,
            namespace=typ.target if typ.kind in ("id", "ref") else None,
            default=default.text if default is not None else None,
            doc=self._comments.get(name.line, ""),
        )
        if self._accept("("):
            what = f"attribute {name.text!r}"
            self._apply_facets(attr, self._facets(_ATTRIBUTE_FACETS, what), name.line)
        if attr.required and default is not None:
            raise self._error(name.line, f"attribute {name.text!r} is required and has a default")
        return _Attr(attr, name.line, default)

    def _type(self, attr: str) -> _Type:
        token = self._ident(f"a type for attribute {attr!r}")
        if token.text in _TARGET_TYPES:
            return self._target_type(token, attr)
        if token.text in _NUMERIC_TYPES:
            kind, dtype = _NUMERIC_TYPES[token.text]
            return _Type(kind, dtype, self._arity(attr))
        if token.text not in _TEXT_TYPES:
            raise self._error(token.line, f"unknown type {token.text!r} of attribute {attr!r}")
        arity = self._arity(attr)
        if token.text in ("bool", "file") and arity is not None:
            raise self._error(token.line, f"{token.text} attribute {attr!r} may not be a vector")
        if token.text == "chars" and (arity is None or arity[1] is None):
            raise self._error(token.line, f"chars attribute {attr!r} needs a bounded length, "
                                          "e.g. chars[3] or chars[1..12]")
        return _Type(_TEXT_TYPES[token.text], None, arity)

    def _target_type(self, token: _Token, attr: str) -> _Type:
        """``enum<x>``, ``enum<x>[]``, ``flags<x>``, ``id<ns>``, ``ref<ns>``."""
        self._expect("<", f"'<' after '{token.text}'")
        target = self._ident(f"a name inside '{token.text}<...>'").text
        self._expect(">", f"'>' to close '{token.text}<{target}'")
        kind = _TARGET_TYPES[token.text]
        if self._accept("["):
            if token.text != "enum":
                raise self._error(token.line, f"{token.text}<{target}> of attribute {attr!r} "
                                              "takes no arity")
            self._expect("]", f"']' after 'enum<{target}>[' (only '[]' lists are allowed)")
            kind = "flags"  # a list of keywords of the enum
        return _Type(kind, target=target)

    def _arity(self, attr: str) -> tuple[int, int | None] | None:
        if not self._accept("["):
            return None
        if self._accept("]"):
            return (0, None)
        low_token = self._next()
        low = self._count(low_token, attr)
        if not self._accept("dotdot"):
            self._expect("]", f"']' or '..' in the arity of attribute {attr!r}")
            if low == 0:
                raise self._error(low_token.line, f"arity [0] of attribute {attr!r} is empty")
            return (low, low)
        high_token = self._next()
        high = self._bound(high_token, attr)
        symbolic = high_token.kind == "ident"
        if high < low or (high == low and not symbolic):
            raise self._error(high_token.line,
                              f"arity [{low}..{high}] of attribute {attr!r} is not increasing")
        self._expect("]", f"']' to close the arity of attribute {attr!r}")
        return (low, high)

    def _count(self, token: _Token, attr: str) -> int:
        if token.kind != "number" or not token.text.isdigit():
            raise self._unexpected(token, f"a count in the arity of attribute {attr!r}")
        return int(token.text)

    def _bound(self, token: _Token, attr: str) -> int:
        if token.kind == "number" and token.text.isdigit():
            return int(token.text)
        if token.kind != "ident":
            raise self._unexpected(token, f"an arity bound for attribute {attr!r}")
        value = self._constants.get(token.text)
        if value is None:
            raise self._error(token.line, f"unknown arity bound {token.text!r} of attribute "
                                          f"{attr!r} (pass it in constants)")
        return value

    def _default(self, attr: str) -> _Default:
        token = self._next()
        if token.kind == "number":
            return _Default(token.text, "number", [token.text])
        if token.kind == "ident":
            return _Default(token.text, "ident", [])
        if token.kind == "string":
            return _Default(token.text, "string", [])
        if token.kind != "{":
            raise self._unexpected(token, f"a default value for attribute {attr!r}")
        numbers = [self._expect("number", f"a number in the default of {attr!r}").text]
        while self._accept(","):
            numbers.append(self._expect("number", f"a number in the default of {attr!r}").text)
        self._expect("}", f"',' or '}}' in the default of attribute {attr!r}")
        return _Default(" ".join(numbers), "list", numbers)

    def _facets(self, known: Mapping[str, frozenset[str]], owner: str) -> dict[str, _Token]:
        """``(a, b=x, c="y")`` after the opening parenthesis; flags map to their own token."""
        facets: dict[str, _Token] = {}
        while True:
            token = self._ident(f"a facet name of {owner}")
            allowed = known.get(token.text)
            if allowed is None:
                raise self._error(token.line, f"unknown facet {token.text!r} of {owner}")
            if token.text in facets:
                raise self._error(token.line, f"duplicate facet {token.text!r} of {owner}")
            facets[token.text] = self._facet_value(token, allowed, owner)
            if self._accept(")"):
                return facets
            self._expect(",", f"',' or ')' in the facets of {owner}")

    def _facet_value(self, name: _Token, allowed: frozenset[str], owner: str) -> _Token:
        if not self._accept("="):
            if allowed:
                raise self._error(name.line, f"facet {name.text!r} of {owner} needs a value")
            return name
        value = self._next()
        if not allowed:
            raise self._error(name.line, f"facet {name.text!r} of {owner} takes no value")
        if value.kind not in allowed:
            expected = " or ".join(_VALUE_NAMES[k] for k in sorted(allowed))
            raise self._unexpected(value, f"{expected} as the value of facet {name.text!r} of "
                                          f"{owner}")
        return value

    def _apply_facets(self, attr: ir.AttributeDef, facets: dict[str, _Token], line: int) -> None:
        """Keep the facets the IR models; check that the rest fit the attribute's kind."""
        numeric = attr.kind in ("int", "real")
        for name in facets:
            if name in ("min", "max", "positive") and not numeric:
                raise self._error(line, f"facet {name!r} needs a numeric attribute, "
                                        f"{attr.name!r} is {attr.kind}")
            if name == "dim" and attr.kind != "real":
                raise self._error(line, f"facet 'dim' needs a real-valued attribute, "
                                        f"{attr.name!r} is {attr.kind}")
        attr.required = "required" in facets
        attr.nodefault = "nodefault" in facets
        if "field" in facets:
            attr.field = facets["field"].text
        if "pattern" in facets:
            attr.pattern = self._pattern(attr, facets["pattern"].text, line)
        low, high = facets.get("min"), facets.get("max")
        if low is not None and high is not None and float(low.text) > float(high.text):
            raise self._error(line, f"facet 'min' of attribute {attr.name!r} exceeds 'max'")

    def _pattern(self, attr: ir.AttributeDef, pattern: str, line: int) -> str:
        if attr.kind not in ("string", "chars"):
            raise self._error(line, f"facet 'pattern' needs a text attribute, "
                                    f"{attr.name!r} is {attr.kind}")
        try:
            re.compile(pattern)
        except re.error as exc:
            raise self._error(line, f"bad pattern of attribute {attr.name!r}: {exc}") from None
        return pattern


# ---------------------------------------------------------------------------- resolver


@dataclass
class _Expansion:
    """An element's members with groups spliced in, in declaration order."""

    # (attribute, its line in the container: its own or that of the outermost 'use')
    attrs: list[tuple[_Attr, int]] = field(default_factory=list[tuple[_Attr, int]])
    # (constraint, written directly in the container rather than in a used group)
    constraints: list[tuple[_Constraint, bool]] = field(
        default_factory=list[tuple[_Constraint, bool]])
    children: list[_Child] = field(default_factory=list[_Child])


class _Resolver:
    """Cross-reference checks and IR construction over parsed declarations."""

    def __init__(self, decls: _Declarations, path: str) -> None:
        self._decls = decls
        self._path = path
        # a namespace exists because some id<ns> declares into it
        self._namespaces = {a.attr.namespace for a in self._all_attributes()
                            if a.attr.kind == "id" and a.attr.namespace is not None}

    def _error(self, line: int, message: str) -> GrammarError:
        return GrammarError(self._path, line, message)

    def resolve(self) -> ir.Schema:
        for group in self._decls.groups.values():
            self._check_group(group)
        for attr in self._all_attributes():
            self._check_attribute(attr)
        elements = {name: self._element(el) for name, el in self._decls.elements.items()}
        root = self._root(elements)
        for element in elements.values():
            element.class_name = naming.class_name(element.name, root)
        enums = {name: e.enum for name, e in self._decls.enums.items()}
        return ir.Schema(mujoco_version="", root=root, enums=enums, elements=elements)

    # -- groups

    def _check_group(self, group: _Group) -> None:
        self._check_cycle(group, ())
        if group.variant:
            for member in group.members:
                if isinstance(member, _Use):
                    raise self._error(member.line,
                                      f"variant group {group.name!r} may not 'use' a group")
                if isinstance(member, _Attr) and member.attr.required:
                    raise self._error(member.line, f"attribute {member.attr.name!r} of variant "
                                                   f"group {group.name!r} may not be required")
        expansion = _Expansion()
        self._expand(group.members, None, expansion)
        self._check_constraints(expansion, f"group {group.name!r}")

    def _check_cycle(self, group: _Group, stack: tuple[str, ...]) -> None:
        for use in (m for m in group.members if isinstance(m, _Use)):
            target = self._group(use)
            if target.name in (*stack, group.name):
                cycle = " -> ".join((*stack, group.name, target.name))
                raise self._error(use.line, f"group use cycle: {cycle}")
            self._check_cycle(target, (*stack, group.name))

    def _group(self, use: _Use) -> _Group:
        group = self._decls.groups.get(use.group)
        if group is None:
            raise self._error(use.line, f"use of undeclared group {use.group!r}")
        return group

    def _expand(self, members: list[_Member], site: int | None, out: _Expansion) -> None:
        """Splice groups in place; ``site`` is the line of the outermost ``use``."""
        for member in members:
            if isinstance(member, _Attr):
                out.attrs.append((member, site or member.line))
            elif isinstance(member, _Use):
                group = self._group(member)
                self._expand(group.members, site or member.line, out)
                if group.variant:
                    bundles = [[m.attr.name] for m in group.members if isinstance(m, _Attr)]
                    variant = ir.ConstraintDef("exclusive", bundles)
                    out.constraints.append((_Constraint(variant, member.line), False))
            elif isinstance(member, _Constraint):
                out.constraints.append((member, site is None))
            else:
                out.children.append(member)

    # -- attributes

    def _all_attributes(self) -> list[_Attr]:
        """Every attribute declaration once, in file order (groups are checked where written)."""
        members = [m for g in self._decls.groups.values() for m in g.members]
        members += [m for e in self._decls.elements.values() for m in e.members]
        attrs = [m for m in members if isinstance(m, _Attr)]
        return sorted(attrs, key=lambda a: a.line)

    def _check_attribute(self, raw: _Attr) -> None:
        attr = raw.attr
        if attr.enum is not None and attr.enum not in self._decls.enums:
            raise self._error(raw.line,
                              f"attribute {attr.name!r} uses undeclared enum {attr.enum!r}")
        if attr.kind == "ref" and attr.namespace not in self._namespaces:
            raise self._error(raw.line, f"attribute {attr.name!r} refers to namespace "
                                        f"{attr.namespace!r}, which no id<{attr.namespace}> "
                                        "declares")
        if raw.default is not None:
            problem = self._default_problem(attr, raw.default)
            if problem:
                raise self._error(raw.line, problem)

    def _default_problem(self, attr: ir.AttributeDef, default: _Default) -> str | None:
        """Why ``default`` does not fit ``attr``, or None."""
        name, text = attr.name, default.text
        if attr.kind in ("id", "ref", "chars"):
            return f"{attr.kind} attribute {name!r} may not have a default"
        if attr.kind in ("keyword", "flags"):
            assert attr.enum is not None
            keywords = self._decls.enums[attr.enum].enum.keywords
            words = text.split() if attr.kind == "flags" else [text]
            bad = [w for w in words if w not in keywords]
            if default.form == "list" or not words or bad:
                return f"default {text!r} of attribute {name!r} is not a keyword of enum " \
                       f"{attr.enum!r}"
            return None
        if attr.kind == "bool":
            ok = default.form == "ident" and text in ("true", "false")
            return None if ok else f"default of bool attribute {name!r} must be true or false"
        if attr.kind in ("string", "file"):
            ok = default.form in ("ident", "string")
            return None if ok else f"default of {attr.kind} attribute {name!r} must be text"
        return self._numeric_default_problem(attr, default)

    @staticmethod
    def _numeric_default_problem(attr: ir.AttributeDef, default: _Default) -> str | None:
        name, count = attr.name, len(default.numbers)
        if default.form not in ("number", "list"):
            return f"default of numeric attribute {name!r} must be numeric"
        if attr.kind == "int" and not all(_INT_RE.fullmatch(n) for n in default.numbers):
            return f"default of int attribute {name!r} must be integers"
        if attr.arity is None:
            return None if default.form == "number" else (
                f"vector default of scalar attribute {name!r}")
        low, high = attr.arity
        if count < low or (high is not None and count > high):
            return f"default of attribute {name!r} has {count} values, arity is " \
                   f"[{low}..{'' if high is None else high}]"
        return None

    # -- elements

    def _element(self, el: _Element) -> ir.ElementDef:
        if el.alias is not None and el.alias not in self._decls.elements:
            raise self._error(el.line, f"element {el.name!r} is an alias of undeclared "
                                       f"element {el.alias!r}")
        expansion = _Expansion()
        self._expand(el.members, None, expansion)
        attributes = self._attributes(el, expansion)
        self._check_constraints(expansion, f"element {el.name!r}")
        return ir.ElementDef(
            name=el.name, tag=el.tag, class_name=naming.class_name(el.name),
            attributes=attributes,
            children=self._children(el, expansion.children),
            constraints=[copy.deepcopy(c.constraint) for c, _ in expansion.constraints],
            struct=el.struct, alias=el.alias, doc=el.doc,
        )

    def _attributes(self, el: _Element, expansion: _Expansion) -> list[ir.AttributeDef]:
        """Fresh copies (groups are shared), rejecting a name declared twice."""
        first: dict[str, int] = {}
        out: list[ir.AttributeDef] = []
        for raw, site in expansion.attrs:
            name = raw.attr.name
            if name in first:
                via = "" if site == raw.line else " (via use)"
                raise self._error(site, f"duplicate attribute {name!r} in element {el.name!r}"
                                        f"{via}, first on line {first[name]}")
            first[name] = site
            out.append(copy.deepcopy(raw.attr))
        return out

    def _check_constraints(self, expansion: _Expansion, owner: str) -> None:
        """Constraints name attributes of their own container (groups spliced in)."""
        names = {raw.attr.name for raw, _ in expansion.attrs}
        for constraint, direct in expansion.constraints:
            unknown = [n for b in constraint.constraint.bundles for n in b if n not in names]
            if direct and unknown:
                raise self._error(constraint.line, f"constraint '{constraint.constraint.kind}' "
                                                   f"names unknown attribute {unknown[0]!r} of "
                                                   f"{owner}")

    def _children(self, el: _Element, children: list[_Child]) -> list[ir.ChildDef]:
        seen: set[str] = set()
        out: list[ir.ChildDef] = []
        for child in children:
            if child.element not in self._decls.elements:
                raise self._error(child.line,
                                  f"child of {el.name!r} names undeclared element "
                                  f"{child.element!r}")
            if child.element in seen:
                raise self._error(child.line, f"duplicate child {child.element!r} of {el.name!r}")
            seen.add(child.element)
            out.append(ir.ChildDef(child.element, child.card, single=child.card in "?!"))
        return out

    def _root(self, elements: dict[str, ir.ElementDef]) -> str:
        """The one element no other lists as a child; alias rows are reached by their alias."""
        listed = {c.element for e in elements.values() for c in e.children if c.element != e.name}
        roots = [e for e in self._decls.elements.values()
                 if e.name not in listed and e.alias is None]
        if not self._decls.elements:
            raise self._error(1, "no element declared")
        if not roots:
            first = next(iter(self._decls.elements.values()))
            raise self._error(first.line, "no root element: every element is another's child")
        if len(roots) > 1:
            names = ", ".join(f"{e.name!r} (line {e.line})" for e in roots)
            raise self._error(roots[1].line, f"ambiguous root: {names} are children of no element")
        return roots[0].name
