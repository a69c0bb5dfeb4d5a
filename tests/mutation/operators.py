"""Machine-made mutants of a solution's SOLUTION blocks: the usual mutation operators, applied by
libclang's exact parse (python3-clang), one change a mutant.

Each mutant is one edit of the solution's text: (exercise, operator, line, start, end, replacement).
Its id is stable while the line it edits keeps its text, so the list of equivalent mutants
(equivalent.txt) survives edits elsewhere in the file.
"""

import hashlib
import math
import re
import struct
from dataclasses import dataclass

import clang.cindex as ci


@dataclass
class Mutant:
    exercise: str     # "07.5"
    operator: str     # "relational", "constant", ...
    line: int         # 1-based line of the solution file
    start: int        # offsets into the file's text
    end: int
    replacement: str
    original: str     # the text replaced
    line_text: str    # the line as written, stripped: what a reader recognises

    @property
    def id(self):
        # The line's text, the change, and which occurrence of that text on the line: not the line
        # number, which moves with every edit above it.
        key = f"{self.exercise}|{self.operator}|{self.line_text}|{self.original}|{self.replacement}|{self.column_key}"
        return hashlib.sha1(key.encode()).hexdigest()[:10]

    column_key: int = 0  # occurrence of `original` on its line

    def describe(self):
        return f"{self.line_text}   [{self.original} -> {self.replacement}]"

    def apply(self, text):
        return text[: self.start] + self.replacement + text[self.end :]


RELATIONAL_NEIGHBOURS = {"<": ["<="], "<=": ["<"], ">": [">="], ">=": [">"], "==": ["!="], "!=": ["=="]}
ARITHMETIC = {"+": ["-"], "-": ["+"], "*": ["/"], "/": ["*"], "+=": ["-="], "-=": ["+="], "*=": ["/="], "/=": ["*="]}
LOGICAL = {"&&": ["||"], "||": ["&&"]}
# Calls a student swaps for their neighbour, and types one narrows by mistake.
CALL_SWAPS = {"min": "max", "max": "min", "floor": "ceil", "ceil": "floor", "fmin": "fmax", "fmax": "fmin"}
TYPE_NARROWING = {
    "double": "float",
    "int64_t": "int32_t",
    "uint64_t": "uint32_t",
    "size_t": "uint32_t",
    "uint32_t": "int32_t",  # unsigned to signed: a table size past 2^31 - 1
    "unsigned": "int",
}
UNARY_DROPPED = {"-", "!", "~"}

_EXERCISE = re.compile(r"//\s*EXERCISE\s+(\d\d\.\w+)")


def solution_blocks(text):
    """(first offset, last offset, exercise) of every SOLUTION BEGIN..END block inside an exercise."""
    blocks = []
    exercise = None
    begin = None
    offset = 0
    for line in text.splitlines(keepends=True):
        m = _EXERCISE.search(line)
        if m:
            exercise = m.group(1)
        stripped = line.strip()
        if stripped == "// SOLUTION BEGIN":
            begin = offset + len(line)
        elif stripped == "// SOLUTION END" and begin is not None:
            if exercise:
                blocks.append((begin, offset, exercise))
            begin = None
        offset += len(line)
    return blocks


def _float_ulp_up(literal):
    body = literal.rstrip("fFlL")
    suffix = literal[len(body):]
    value = float(body)
    if suffix.lower() == "f":
        bits = struct.unpack("<I", struct.pack("<f", value))[0]
        up = struct.unpack("<f", struct.pack("<I", bits + (1 if value >= 0 else -1)))[0] if value != 0 else 1.4e-45
        return f"{up:.9g}" + suffix if "e" in f"{up:.9g}" or "." in f"{up:.9g}" else f"{up:.9g}.0" + suffix
    up = math.nextafter(value, math.inf)
    text = repr(up)
    return text + suffix


def _integer_neighbours(literal):
    m = re.match(r"^(0[xX][0-9a-fA-F']+|\d[\d']*)([uUlL]*)$", literal)
    if not m:
        return []
    value = int(m.group(1).replace("'", ""), 0)
    suffix = m.group(2)
    out = [str(value + 1) + suffix]
    if value > 0:
        out.append(str(value - 1) + suffix)
    return out


class Generator:
    def __init__(self, path, args):
        self.path = path
        with open(path, encoding="utf-8") as f:
            self.text = f.read()
        self.line_starts = [0]
        for i, c in enumerate(self.text):
            if c == "\n":
                self.line_starts.append(i + 1)
        index = ci.Index.create()
        self.tu = index.parse(path, args=["-x", "c++"] + args)
        errors = [d for d in self.tu.diagnostics if d.severity >= ci.Diagnostic.Error]
        if errors:
            raise RuntimeError(f"{path}: libclang cannot parse it: {errors[0]}")
        self.blocks = solution_blocks(self.text)

    def _exercise_at(self, offset):
        for begin, end, exercise in self.blocks:
            if begin <= offset < end:
                return exercise
        return None

    def _in_file(self, location):
        return location.file is not None and location.file.name == self.path

    def _mutant(self, exercise, operator, start, end, replacement):
        line = self.text.count("\n", 0, start) + 1
        line_begin = self.line_starts[line - 1]
        line_end = self.text.find("\n", start)
        line_text = self.text[line_begin:line_end]
        original = self.text[start:end]
        occurrence = line_text[: start - line_begin].count(original)
        return Mutant(exercise, operator, line, start, end, replacement, original, line_text.strip(), occurrence)

    def mutants(self):
        found = []
        tokens = [t for t in self.tu.get_tokens(extent=self.tu.cursor.extent) if self._in_file(t.location)]
        for i, tok in enumerate(tokens):
            start = tok.extent.start.offset
            exercise = self._exercise_at(start)
            if not exercise:
                continue
            # An array's size in its declaration (float u[4]): one more slot changes nothing.
            if 0 < i < len(tokens) - 1 and tokens[i - 1].spelling == "[" and tokens[i + 1].spelling == "]" and \
                    tokens[i - 1].cursor.kind == ci.CursorKind.VAR_DECL:
                continue
            found.extend(self._token_mutants(tok, exercise, start, tok.extent.end.offset))
        found.extend(self._cursor_mutants(self.tu.cursor))
        # One mutant per distinct edit.
        unique = {}
        for m in found:
            unique.setdefault((m.start, m.end, m.replacement), m)
        return sorted(unique.values(), key=lambda m: (m.start, m.replacement))

    def _token_mutants(self, tok, exercise, start, end):
        s = tok.spelling
        kind = tok.cursor.kind
        out = []
        is_operator = kind in (ci.CursorKind.BINARY_OPERATOR, ci.CursorKind.COMPOUND_ASSIGNMENT_OPERATOR) or (
            kind == ci.CursorKind.CALL_EXPR and tok.cursor.spelling == "operator" + s)
        if tok.kind == ci.TokenKind.PUNCTUATION and is_operator:
            for table, name in ((RELATIONAL_NEIGHBOURS, "relational"), (ARITHMETIC, "arithmetic"), (LOGICAL, "logical")):
                for r in table.get(s, []):
                    out.append(self._mutant(exercise, name, start, end, r))
        elif tok.kind == ci.TokenKind.PUNCTUATION and kind == ci.CursorKind.UNARY_OPERATOR and s in UNARY_DROPPED:
            out.append(self._mutant(exercise, "unary dropped", start, end, ""))
        elif tok.kind == ci.TokenKind.LITERAL and kind == ci.CursorKind.INTEGER_LITERAL:
            for r in _integer_neighbours(s):
                out.append(self._mutant(exercise, "constant by one", start, end, r))
        elif tok.kind == ci.TokenKind.LITERAL and kind == ci.CursorKind.FLOATING_LITERAL:
            out.append(self._mutant(exercise, "constant by one ulp", start, end, _float_ulp_up(s)))
        elif tok.kind == ci.TokenKind.KEYWORD and s in ("true", "false"):
            out.append(self._mutant(exercise, "boolean flipped", start, end, "false" if s == "true" else "true"))
        elif s in TYPE_NARROWING and tok.kind in (ci.TokenKind.KEYWORD, ci.TokenKind.IDENTIFIER):
            out.append(self._mutant(exercise, "narrower type", start, end, TYPE_NARROWING[s]))
        elif tok.kind == ci.TokenKind.IDENTIFIER and s in CALL_SWAPS and kind in (
                ci.CursorKind.DECL_REF_EXPR, ci.CursorKind.OVERLOADED_DECL_REF, ci.CursorKind.CALL_EXPR):
            out.append(self._mutant(exercise, "call swapped", start, end, CALL_SWAPS[s]))
        return out

    def _cursor_mutants(self, root):
        out = []
        for c in root.walk_preorder():
            if not self._in_file(c.location):
                continue
            start = c.extent.start.offset
            exercise = self._exercise_at(start)
            if not exercise or self._exercise_at(c.extent.end.offset - 1) != exercise:
                continue
            out.extend(self._statement_mutants(c, exercise))
        return out

    def _text(self, cursor):
        return self.text[cursor.extent.start.offset:cursor.extent.end.offset]

    def _statement_mutants(self, c, exercise):
        out = []
        k = c.kind
        start, end = c.extent.start.offset, c.extent.end.offset
        # A statement removed: an expression statement of a block (an assignment, a call, ++) or a
        # continue/break. Declarations and returns are left: removing them does not compile.
        if k in (ci.CursorKind.CONTINUE_STMT, ci.CursorKind.BREAK_STMT):
            out.append(self._mutant(exercise, "statement removed", start, end, "(void)0"))
        elif k == ci.CursorKind.COMPOUND_STMT:
            for child in c.get_children():
                if child.kind in (ci.CursorKind.BINARY_OPERATOR, ci.CursorKind.COMPOUND_ASSIGNMENT_OPERATOR,
                                  ci.CursorKind.CALL_EXPR, ci.CursorKind.UNARY_OPERATOR):
                    out.append(self._mutant(exercise, "statement removed", child.extent.start.offset,
                                            child.extent.end.offset, "(void)0"))
        elif k == ci.CursorKind.IF_STMT:
            children = list(c.get_children())
            if children and children[0].kind not in (ci.CursorKind.VAR_DECL, ci.CursorKind.DECL_STMT):
                cond = children[0]
                for value in ("true", "false"):
                    out.append(self._mutant(exercise, "condition forced", cond.extent.start.offset,
                                            cond.extent.end.offset, value))
        elif k == ci.CursorKind.CALL_EXPR and c.spelling in ("nextafter", "nextafterf"):
            args = list(c.get_arguments())
            if args:
                out.append(self._mutant(exercise, "nextafter dropped", start, end, "(" + self._text(args[0]) + ")"))
        elif k == ci.CursorKind.BINARY_OPERATOR and c.type.spelling in ("float", "double"):
            out.extend(self._regrouped_sum(c, exercise))
        return out

    def _operator_after(self, lhs, cursor):
        for tok in cursor.get_tokens():
            if tok.extent.start.offset >= lhs.extent.end.offset:
                return tok.spelling
        return None

    def _regrouped_sum(self, c, exercise):
        # (a + b) + c, written a + b + c, summed as a + (b + c): another rounding of the same sum.
        children = list(c.get_children())
        if len(children) != 2 or self._operator_after(children[0], c) != "+":
            return []
        lhs, rhs = children
        while lhs.kind == ci.CursorKind.UNEXPOSED_EXPR and len(list(lhs.get_children())) == 1:
            lhs = next(lhs.get_children())
        if lhs.kind != ci.CursorKind.BINARY_OPERATOR or self._operator_after(lhs, lhs) != "+":
            return []
        a, b = list(lhs.get_children())
        text = self._text(a) + " + (" + self._text(b) + " + " + self._text(rhs) + ")"
        return [self._mutant(exercise, "sum regrouped", c.extent.start.offset, c.extent.end.offset, text)]
