#!/usr/bin/env python3
# Usage: scripts/long_functions.py [--max-lines N] [PATH ...]   (defaults: 100, the source folders)
"""Lists the functions longer than --max-lines, as FILE:LINE: NAME (N lines), longest first.

A function's length runs from the first line of its definition (template line, return type) to
its closing brace, for C++ (.cpp, .h, .cc, .hpp) and Python (.py). C++ is read as text: comments,
strings and preprocessor lines are blanked, then braces are matched; a brace opens a function
body when the text before it is a call-like head (name, parameters) followed only by qualifiers,
a trailing return type or a constructor's initializer list. Lambdas count within the function
that holds them. Exit status 1 when any function is too long, 0 otherwise."""
import argparse
import ast
import os
import re
import sys

CPP_ENDINGS = (".cpp", ".h", ".cc", ".hpp")
NOT_FUNCTIONS = {"if", "for", "while", "switch", "catch", "return", "sizeof", "decltype", "alignof",
                 "static_assert", "alignas", "__attribute__"}
NAME = re.compile(r"((?:[A-Za-z_]\w*\s*::\s*)*"
                  r"(?:operator\s*\(\s*\)|operator\s*[^\s\w(]+|~?[A-Za-z_]\w*)|\]\s*)"
                  r"\s*(?:<[^(){};]*>)?\s*\(")
TAIL = re.compile(r"^(?:\s|const|volatile|noexcept|override|final|mutable|&|->[^{};]*"
                  r"|\[\[[^\]]*\]\])*(:.*)?$", re.S)


def blank(text):
    """The text with comments, string and character literals and preprocessor lines as spaces
    (newlines kept, so line numbers stay)."""
    token = re.compile(r'//[^\n]*|/\*.*?\*/|R"(?P<d>[^(\s]*)\(.*?\)(?P=d)"|"(?:\\.|[^"\\\n])*"'
                       r"|'(?:\\.|[^'\\\n])*'|^[ \t]*#(?:[^\n]*\\\n)*[^\n]*", re.S | re.M)
    return token.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)


def function_head(head):
    """The function's name when `head` (the text before a brace) opens a function body."""
    head = re.sub(r"^\s*template\s*<[^{};]*?>(?=\s*[A-Za-z_])", "", head)
    match = NAME.search(head)
    if not match or match.group(1).split("::")[-1].strip() in NOT_FUNCTIONS:
        return None
    depth, i = 0, match.end() - 1
    for i in range(match.end() - 1, len(head)):
        depth += {"(": 1, ")": -1}.get(head[i], 0)
        if depth == 0:
            break
    if depth != 0 or not TAIL.match(head[i + 1:]):
        return None
    return re.sub(r"\s+", "", match.group(1)) or "lambda"


def cpp_functions(text):
    """(first line, last line, name) of every function body outside another function."""
    text = blank(text)
    out, stack, head_start = [], [], 0  # stack: (kind, start offset, name)
    for pos, c in enumerate(text):
        if c == ";" and not any(k == "function" for k, _, _ in stack):
            head_start = pos + 1
        elif c == "{":
            if any(k == "function" for k, _, _ in stack):
                stack.append(("block", pos, None))
                continue
            head = text[head_start:pos]
            name = function_head(head)
            # A brace initializer in a constructor's initializer list: the head goes on.
            if name and re.search(r"\)\s*[^()]*:\s*[^;]*[\w>]\s*$", head) and \
                    re.search(r"[\w>]\s*$", head):
                stack.append(("init", pos, None))
                continue
            start = head_start + len(head) - len(head.lstrip())
            stack.append(("function", start, name) if name else ("scope", pos, None))
            head_start = pos + 1
        elif c == "}" and stack:
            kind, start, name = stack.pop()
            if kind == "function":
                out.append((text.count("\n", 0, start) + 1, text.count("\n", 0, pos) + 1, name))
            if kind != "init" and not any(k == "function" for k, _, _ in stack):
                head_start = pos + 1
    return out


def python_functions(text, path):
    tree = ast.parse(text, path)
    return [(n.lineno - len(n.decorator_list), n.end_lineno, n.name) for n in ast.walk(tree)
            if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef))]


def source_files(paths):
    for root in paths:
        if os.path.isfile(root):
            yield root
        for folder, dirs, files in os.walk(root):
            dirs[:] = sorted(d for d in dirs if d not in ("node_modules", "vendor", "__pycache__"))
            for f in sorted(files):
                if f.endswith(CPP_ENDINGS + (".py",)):
                    yield os.path.join(folder, f)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--max-lines", type=int, default=100)
    parser.add_argument("paths", nargs="*", default=["lib", "proxies", "apps", "fuzz", "scripts"])
    args = parser.parse_args()
    found = []
    for path in source_files(args.paths):
        with open(path, encoding="utf-8", errors="replace") as f:
            text = f.read()
        functions = python_functions(text, path) if path.endswith(".py") else cpp_functions(text)
        found += [(last - first + 1, path, first, name) for first, last, name in functions
                  if last - first + 1 > args.max_lines]
    for lines, path, first, name in sorted(found, key=lambda f: (-f[0], f[1], f[2])):
        print(f"{path}:{first}: {name} ({lines} lines)")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
