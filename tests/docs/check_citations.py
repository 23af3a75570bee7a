#!/usr/bin/env python3
"""Fails when a comment in the sources cites a paper's equation in any but the one form.

Usage: check_citations.py <repository root>   exit 0 when every citation has the form of
                                              docs/errata.md ("Citations") and names an equation
                                              its paper has, 1 (one line per offence) otherwise
       check_citations.py --self-test         checks the checker on made-up lines

The form (docs/errata.md, "Citations"): `[PET-ERG eq. (6)]`, `[Waypoint eqs. (17)-(22)]`,
`[ConReach eqs. (20), (28)]`; sections, algorithms, theorems, tables as `[ConReach Alg. 1]`.
The short names and each paper's equation numbers are read from the table after the marker
`<!-- equations: ... -->` in docs/errata.md, so the list has one definition.

Scanned: the C++ sources under src/ and python/src/. An offence is
- a bracket citation `[NAME ...]` whose NAME is not a short name, whose kind is not one of
  eq./eqs./Sec./Alg./Thm./Lemma/Prop./Def./Remark/Table/Fig./Assumption/Appendix, or whose
  equation list is malformed or names a number the paper does not have;
- outside a bracket citation: "eq." / "eqs." / "equation" followed by a number, a range
  "(5)-(6)", a number after a word that names a formula ("law (3)", "LMI (10)"), "(6) of the",
  and the paper names that are not the short ones ("reachability paper", "PET-ERG paper", ...).
"""
import os
import re
import sys

SCAN = ("src", "python/src")
SUFFIXES = (".cpp", ".hpp", ".h")
ERRATA = "docs/errata.md"
MARKER = "<!-- equations:"
KINDS = ("eq.", "eqs.", "Sec.", "Alg.", "Thm.", "Lemma", "Prop.", "Def.", "Remark", "Table",
         "Fig.", "Assumption", "Appendix")

NUMBER = r"(?<![\w)])\(\d{1,2}[a-z]?\)"
EQUATION_LIST = re.compile(r"%s(?:\s*(?:-|–|,|, and| and)\s*%s)*" % (NUMBER, NUMBER))
BRACKET = re.compile(r"\[([A-Za-z][A-Za-z-]*) (\S+) ([^\]]*)\]")
# Outside a bracket citation these are equation citations in another form.
LOOSE = [
    (re.compile(r"\b[Ee]qs?\.\s*\(?\d"), "an \"eq.\" citation outside the bracket form"),
    (re.compile(r"\b[Ee]quations?\s*\(\d"), "an \"equation (N)\" citation outside the bracket form"),
    (re.compile(r"%s\s*(?:-|–)\s*%s" % (NUMBER, NUMBER)), "an equation range outside the bracket form"),
    (re.compile(r"\b(?:law|laws|LMI|SDP|field|trigger|condition|inequality|formula|dynamics|"
                r"kinematics|rule|update|threshold|constraint|constraints|metric|bound|"
                r"system|margin|PID|controller|representation|cones?|limit)\s+%s" % NUMBER),
     "an equation number after a formula's name, outside the bracket form"),
    (re.compile(r"%s\s+of the\b" % NUMBER), "\"(N) of the ...\" outside the bracket form"),
    (re.compile(r"\b(?:[Rr]eachability|[Rr]each|[Cc]ontraction[- ]reachability|[Cc]ontraction|"
                r"waypoint|waypoint-tracking|[Gg]overnor) paper\b"),
     "a paper named otherwise than by its short name (docs/errata.md)"),
]


def equation_table(root):
    """{short name: set of equation numbers} from the marked table of docs/errata.md."""
    with open(os.path.join(root, ERRATA), encoding="utf-8") as f:
        text = f.read()
    at = text.find(MARKER)
    if at < 0:
        raise SystemExit(f"check_citations: {ERRATA} has no line starting {MARKER!r}")
    table = {}
    for line in text[at:].splitlines()[1:]:
        if not line.startswith("|"):
            if table:
                break
            continue
        cells = [c.strip() for c in line.strip("|").split("|")]
        if len(cells) != 2 or cells[0] in ("paper", "---"):
            continue
        table[cells[0]] = expand_numbers(cells[1])
    if not table:
        raise SystemExit(f"check_citations: no equation table after {MARKER!r} in {ERRATA}")
    return table


def expand_numbers(text):
    """`(1), (3)-(5), (13a)` -> {"1", "3", "4", "5", "13a"}."""
    out = set()
    for part in re.split(r",\s*", text):
        m = re.fullmatch(r"\((\d+)\)\s*-\s*\((\d+)\)", part.strip())
        if m:
            out.update(str(n) for n in range(int(m.group(1)), int(m.group(2)) + 1))
            continue
        m = re.fullmatch(r"\((\d+[a-z]?)\)", part.strip())
        if not m:
            raise SystemExit(f"check_citations: cannot read {part!r} in the table of {ERRATA}")
        out.add(m.group(1))
    return out


def numbers_of(body):
    """The equation numbers of an equation list `(5)-(7), (9)`; a range's inner ones too."""
    out = []
    for a, b in re.findall(r"\((\d+[a-z]?)\)\s*(?:-|–)\s*\((\d+[a-z]?)\)", body):
        out += [a, b]
        if a.isdigit() and b.isdigit():
            out += [str(n) for n in range(int(a) + 1, int(b))]
    out += re.findall(r"\((\d+[a-z]?)\)", body)
    return out


def bracket_offence(m, table):
    """Why the bracket citation m is wrong, or None."""
    name, kind, body = m.group(1), m.group(2), m.group(3).strip()
    if name not in table:
        return None if kind not in KINDS else f"[{name} ...]: {name} is not a paper's short name"
    if kind not in KINDS:
        return f"[{name} {kind} ...]: {kind} is not a citation kind ({', '.join(KINDS)})"
    if kind in ("eq.", "eqs."):
        if not EQUATION_LIST.fullmatch(body):
            return f"[{name} {kind} {body}]: not an equation list like (6) or (5)-(6)"
        numbers = numbers_of(body)
        if (kind == "eq.") != (len(set(numbers)) == 1):
            return f"[{name} {kind} {body}]: \"eq.\" for one equation, \"eqs.\" for several"
        missing = [n for n in numbers if n not in table[name]]
        if missing:
            return f"[{name} {kind} {body}]: {name} has no equation ({missing[0]})"
    return None


def prose(text):
    """text with everything but comments and string literals blanked (newlines kept): only
    prose can cite, and `(3) - (4)` in code is arithmetic."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(text[i:j])
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(text[i:j])
            i = j
        elif c == "R" and text.startswith('"', i + 1) and (i == 0 or not text[i - 1].isalnum()):
            m = re.match(r'R"([^(\s]*)\(', text[i:])
            end = text.find(")" + m.group(1) + '"', i) if m else -1
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append(text[i:j])
            i = j
        elif c == '"' or c == "'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(text[i:j + 1])
            i = j + 1
        else:
            out.append("\n" if c == "\n" else " ")
            i += 1
    return "".join(out)


def offences(text, table):
    """(line, message) of every offence in a source text."""
    found = []
    for lineno, line in enumerate(prose(text).splitlines(), 1):
        rest = line
        for m in BRACKET.finditer(line):
            why = bracket_offence(m, table)
            if why:
                found.append((lineno, why))
            if m.group(1) in table:
                rest = rest.replace(m.group(0), " " * len(m.group(0)))
        for pattern, why in LOOSE:
            m = pattern.search(rest)
            if m:
                found.append((lineno, f"{why}: \"{rest[max(0, m.start() - 20):m.end() + 10].strip()}\""))
    return found


def scanned_files(root):
    for top in SCAN:
        for dirpath, dirnames, filenames in os.walk(os.path.join(root, top)):
            dirnames.sort()
            for name in sorted(filenames):
                if name.endswith(SUFFIXES):
                    yield os.path.relpath(os.path.join(dirpath, name), root)


def check(root):
    table = equation_table(root)
    bad = []
    cited = 0
    for rel in scanned_files(root):
        with open(os.path.join(root, rel), encoding="utf-8") as f:
            text = f.read()
        cited += sum(1 for m in BRACKET.finditer(text) if m.group(1) in table)
        bad += [(rel, line, why) for line, why in offences(text, table)]
    return bad, cited


def self_test():
    """Each made-up bad line is found, for its reason; the good lines pass."""
    table = {"PET-ERG": expand_numbers("(1), (2a), (2b), (3)-(6)"),
             "Waypoint": expand_numbers("(1)-(30)")}
    good = ["/// PD law [PET-ERG eq. (3)] and trigger [PET-ERG eqs. (5)-(6)].",
            "/// cones [PET-ERG eq. (2b)]; [Waypoint eqs. (17), (22)]; [Waypoint Alg. 1]",
            "x = v[0] + a[i] * (3) - (4);  // not a citation: code",
            "/// [Waypoint eqs. (12)-(14), (16)] and [PET-ERG Sec. V]"]
    bad = [("/// the PD law (3) of the letter", "formula's name"),
           ("/// eq. (6) of the PET-ERG paper", "\"eq.\" citation"),
           ("/// eqs. (5)-(6)", "\"eq.\" citation"),
           ("/// (5)-(6) hold", "range"),
           ("/// [PET-ERG eq. (7)]", "has no equation (7)"),
           ("/// [PET-ERG eq. (5)-(6)]", "\"eq.\" for one"),
           ("/// [PET-ERG eqs. (5)]", "\"eq.\" for one"),
           ("/// [PET-ERG eqn. 5]", "not a citation kind"),
           ("/// [PET-ERG eq. 5]", "not an equation list"),
           ("/// see the reachability paper", "short name"),
           ('m.def("f", &f, "PD law (3) of the letter");', "formula's name"),
           ("/// equation (21) gives", "\"equation (N)\"")]
    failures = []
    for line in good:
        if offences(line, table):
            failures.append(f"flagged a good line: {line!r}: {offences(line, table)}")
    for line, reason in bad:
        found = offences(line, table)
        if not any(reason in why for _, why in found):
            failures.append(f"missed {line!r} (expected {reason!r}), found {found}")
    for f in failures:
        print(f"check_citations self-test: {f}")
    if not failures:
        print(f"check_citations self-test: ok ({len(good)} good, {len(bad)} bad lines)")
    return 1 if failures else 0


def main(argv):
    if len(argv) == 2 and argv[1] == "--self-test":
        return self_test()
    if len(argv) != 2 or not os.path.isdir(argv[1]):
        print("usage: check_citations.py <repository root> | --self-test", file=sys.stderr)
        return 2
    bad, cited = check(argv[1])
    for rel, line, why in bad:
        print(f"{rel}:{line}: {why}")
    print(f"check_citations: {cited} citations in the bracket form, {len(bad)} offences")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
