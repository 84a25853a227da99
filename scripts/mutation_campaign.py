#!/usr/bin/env python3
"""Seeded campaign of mutated inputs: mbfem must refuse, never crash.

Issue 29's must-show. Small, fast shipped inputs (SEEDS) are copied into a
run folder each, with their includes expanded and their mesh copied next
to them, and one or two random mutations are applied to each copy: a line
deleted, duplicated or swapped; a number made 0, -1, nan, inf, 1e308,
1e-320 or a whole number past 32 or 64 bits; trailing junk; ids in lists
duplicated or swapped; function expressions, constants and variable names
broken; the output folder or base name made odd (empty, a regular file's
subfolder, a path past PATH_MAX; always relative, inside the run folder);
the mesh truncated, bytes flipped, element lines dropped, node
coordinates made non-finite, the mesh file missing; the dimension changed;
subsection/end unbalanced; includes of the file itself or of missing
files. One run in 33 is a fault run instead: an unmutated seed sent
SIGTERM after a random delay (0.05 to 2 s), which must end within 10 s.

Each run has a verdict:

  CRASH            killed by a signal we did not send, an exit code of 128
                   or more that our signal does not explain, or a core file
  HANG             still running after --timeout (then SIGTERM, 5 s, SIGKILL)
                   or, in a fault run, 10 s after our SIGTERM
  ESCAPE           a result file written outside the run folder (in /)
  UNKNOWN          'unknown error' on stderr
  RAW              raw library text on stderr (RAW_PATTERNS below)
  NOMSG            a non-zero exit without 'mbfem: error' and a message
  PART             a *.part file left in the run folder after the run
  PVD              a .pvd file naming a file that is not there
  NONFINITE_EXIT0  exit 0, but stdout, a CSV or a VTU holds nan or inf
  OK               otherwise: exit 0, refused (1), a contact verdict
                   (2, 3, 4), stopped by our SIGTERM (exit 143 and
                   mbfem's message) or killed by it (before mbfem
                   installs its handler: MPI start-up, order studies)

The mutations are a pure function of --seed and the run's index (a
random.Random per run), so --jobs does not change them and --test output
is fit for a stored comparison.

  python3 scripts/mutation_campaign.py --mbfem build/mbfem --work DIR
      [--count 1000] [--seed 29] [--timeout 60] [--jobs 1] [--test]
      [--list] [--check-seeds]

Prints one line per run (index, seed input, mutations, verdict, exit code,
first line of the error message) and a summary of the counts per verdict,
and exits with 1 if any run is not OK. --list prints the mutations without
running them; --check-seeds runs every seed unmutated and prints its exit
code and time. --test leaves out times and paths, and the exit code and
message of fault runs (they depend on timing). The run folders stay in
DIR/NNNN for inspection (stdout.txt, stderr.txt, input.prm, mesh.msh).
mbfem and the libmbfem-lib.so beside it are copied to DIR/bin first and
run from there, so that a rebuild during the campaign cannot change them.
"""

import argparse
import array
import base64
import math
import os
import random
import re
import resource
import shutil
import signal
import struct
import subprocess
import sys
import tempfile
import time
import zlib
from concurrent.futures import ThreadPoolExecutor

SOURCE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# Small inputs that run in about a second or less each, sorted: 2D and 3D,
# generated and gmsh meshes, contact, in-situ stress and excavation, an
# order study, a JSON input. '.prm.in' files have @SOURCE_DIR@ = tests/.
SEEDS = (
    "parameters/incline_6deg.prm",
    "parameters/toppling_pair.prm",
    "tests/column_self_weight_3d.prm",
    "tests/column_self_weight_3d_json.json",
    "tests/drag_3d.prm",
    "tests/excavation_lame.prm",
    "tests/geostatic_stage.prm",
    "tests/gmsh_mesh.prm.in",
    "tests/hertz_mindlin_p3.prm.in",
    "tests/order_study_timoshenko.prm.in",
    "tests/square_2x2_push.prm",
    "tests/stack_under_gravity_3d.prm",
    "tests/state_incline_35.prm.in",
    "tests/tensile_break.prm",
    "tests/timoshenko_cantilever.prm.in",
)

# Raw library text that a user must never see on stderr: deal.II's
# exception dump, the C++ runtime's and the standard library's own
# messages. (name, regular expression).
RAW_PATTERNS = (
    ("filesystem error", r"filesystem error"),
    ("deal.II ExcMessage dump",
     r"This exception -- which is used in many places"),
    ("bad_alloc", r"bad_alloc"),
    ("deal.II dump", r"An error occurred in line"),
    ("stack trace", r"Stacktrace"),
    ("terminate", r"terminate called"),
    ("what()", r"what\(\):"),
    ("dump rule", r"-{40,}"),
    ("basic_string", r"basic_string"),
    ("stoi/stod/stoul", r"\bsto(?:i|d|ul|ull|l|ll|f)\b"),
    ("vector::_M", r"vector::_M"),
    ("deal.II additional information", r"Additional information:"),
    ("deal.II violated condition", r"The violated condition was"),
    ("deal.II exception class", r"\bExc[A-Z][A-Za-z]*"),
    ("std:: exception", r"\bstd::[a-z_]+"),
    ("boost", r"boost::|<unspecified file>"),
    ("assertion", r"Assertion .* failed"),
    ("muParser dump", r"^(?:Message|Formula|Token|Position|Errc):\s+<"),
    ("Open MPI", r"ORTE_ERROR_LOG|PMIX_ERROR|MPI_ABORT|\borted\b"),
)
RAW = tuple((name, re.compile(pattern, re.M))
            for name, pattern in RAW_PATTERNS)

FAILING = ("CRASH", "HANG", "ESCAPE", "UNKNOWN", "RAW", "NOMSG", "PART",
           "PVD", "NONFINITE_EXIT0")
VERDICTS = FAILING + ("OK",)

FAULT_EVERY = 33           # run i is a fault run if i % 33 == 16
FAULT_GRACE = 10.          # seconds a SIGTERM'd run has to end
KILL_GRACE = 5.            # seconds between SIGTERM and SIGKILL on timeout
ORTED_GRACE = 1.           # seconds to wait for orted's words on a kill
ENVIRONMENT = {"OMPI_ALLOW_RUN_AS_ROOT": "1",
               "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1",
               "OMP_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1"}

NONFINITE = re.compile(r"(?<![\w.])[-+]?(?:nan|inf(?:inity)?)(?!\w)", re.I)
SET_LINE = re.compile(r"^(\s*set\s+)([^=]*?)(\s*=[ \t]*)([^#]*?)"
                      r"(\s*(?:#.*)?)$", re.I)
JSON_PAIR = re.compile(r'"([^"{}]*)"\s*:\s*"([^"]*)"')
NUMBER = re.compile(r"(?<![\w.])[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
                    r"(?![\w.])")
INTEGER = re.compile(r"(?<![\w.-])\d+(?![\w.])")

# Replacements.
ODD_NUMBERS = ("0", "-1", "nan", "inf", "-inf", "1e308", "-1e308", "1e-320",
               "4294967296", "99999999999999999999", "", "2147483648", "-0",
               "1e999", "0.5")
JUNK = (",", "0.5,", " 0.5,", ", 1, 1", " 1, 1", " x,y,t junk", ";", " :",
        " \\", "\t", " 1e999", ",,")
ODD_IDS = ("-1", "99", "65535", "4294967295", "4294967296", "2147483647",
           "10000", "0")
EXPRESSIONS = ("=1", "x=1", "t=2", "1,2,3", "1;2;3;4", "", "x", "1/0",
               "sqrt(-1)", "1e308*1e308", "t*1e308", "(", "exp(1000)",
               "0;0", "y^99999", "x;y;z;t", "log(0)", "1e999", "0*t;0*t;0*t")
CONSTANTS = ("=1", "x=1", "t=2", "a=1, a=2", "pi=3", "a=", "a=nan",
             "a=1e999", "1,2,3", "a=1;b=2", "a b=1", "x=1, y=2", "e=2")
VARIABLES = ("x,y,t", "x,y,z,t", "t", "x,x,t", "", "1,2,3", "x,y",
             "a,b,c,d,e", "x y t", "x,y,z")
DIMENSIONS = ("2", "3", "1", "4", "0", "", "2.5", "3 3", "-1",
              "99999999999999999999")
LONG_NAME = "n" * 300                              # past NAME_MAX (255)
LONG_PATH = "/".join(["d" * 250] * 20)             # past PATH_MAX (4096)
DIRECTORIES = ("", "   ", "afile/sub", "afile", LONG_NAME, LONG_PATH,
               "results/./x", "out put", "r\u00e9sultats", "res\\ults",
               "results//x", "mesh.msh", "input.prm/sub", "-")
BASE_NAMES = ("", "a/b", LONG_NAME, ".", "..", " ", "x.pvd", "-", "a\\b")
TABLE_FILES = ("", "sub/t.csv", LONG_NAME, ".", "afile/t.csv", "t.csv.part")
MESH_FILES = ("missing.msh", "no_folder/mesh.msh", "", ".", "afile/x.msh",
              "mesh.msh/", "MESH.MSH", "input.prm")
MESH_NUMBERS = ("nan", "inf", "-inf", "1e308", "0", "-1", "1e-320",
                "4294967296", "99999999999999999999", "")


# -- Seeds -----------------------------------------------------------------

class Seed:
    """A seed input with its includes expanded: 'lines' of the input,
    'mesh' the absolute path of its mesh file (or None), 'ext'."""

    def __init__(self, name):
        self.name = name
        path = os.path.join(SOURCE, name)
        self.ext = ".json" if name.endswith(".json") else ".prm"
        self.mesh = None
        if self.ext == ".json":
            self.lines = open(path).read().splitlines()
        else:
            self.lines = []
            self.expand(path)

    def expand(self, path):
        """Appends the lines of 'path', includes expanded, comments and
        blank lines left out, a mesh file named 'mesh.msh'."""
        text = open(path).read()
        if path.endswith(".in"):
            text = text.replace("@SOURCE_DIR@", os.path.join(SOURCE, "tests"))
        for line in text.splitlines():
            code = line.split("#")[0].strip()
            if not code:
                continue
            if code.lower().startswith("include "):
                self.expand(resolve(code[8:].strip(), path))
                continue
            m = SET_LINE.match(line)
            if m and m.group(2).strip() == "Mesh file" and m.group(4).strip():
                self.mesh = resolve(m.group(4).strip(), path)
                line = m.group(1) + "Mesh file" + m.group(3) + "mesh.msh"
            self.lines.append(line.rstrip())


def resolve(written, including_file):
    """A path as mbfem takes it: relative to the folder of the file."""
    if os.path.isabs(written):
        return os.path.normpath(written)
    return os.path.normpath(os.path.join(os.path.dirname(including_file),
                                         written))


# -- Cases and their mutations ---------------------------------------------

class Case:
    """The files of one run: the input's lines, the mesh's bytes (or None),
    other files by name."""

    def __init__(self, seed):
        self.seed = seed
        self.ext = seed.ext
        self.lines = list(seed.lines)
        self.mesh = (bytearray(open(seed.mesh, "rb").read())
                     if seed.mesh else None)
        self.extra = {}

    def input_name(self):
        return "input" + self.ext

    def entries(self):
        """(line index, key, start, end) of every value, in order."""
        found = []
        for i, line in enumerate(self.lines):
            if self.ext == ".json":
                for m in JSON_PAIR.finditer(line):
                    found.append((i, m.group(1), m.start(2), m.end(2)))
            else:
                m = SET_LINE.match(line)
                if m:
                    found.append((i, m.group(2).strip(), m.start(4),
                                  m.end(4)))
        return found

    def value(self, entry):
        i, _, start, end = entry
        return self.lines[i][start:end]

    def set_value(self, entry, new):
        i, _, start, end = entry
        if self.ext == ".json":
            new = new.replace("\\", "\\\\")
        self.lines[i] = self.lines[i][:start] + new + self.lines[i][end:]

    def code_lines(self):
        """Indices of the lines that are not comments."""
        return [i for i, line in enumerate(self.lines)
                if line.strip() and not line.strip().startswith("#")]

    def put(self, section, key, new):
        """Sets 'key' (of subsection 'section', None at the top) to 'new',
        inserting the entry where it is missing."""
        for entry in self.entries():
            if entry[1] == key:
                self.set_value(entry, new)
                return
        if self.ext == ".json":
            self.put_json(section, key, new)
        elif section is None:
            self.lines.insert(0, "set %s = %s" % (key, new))
        else:
            for i, line in enumerate(self.lines):
                if re.match(r"\s*subsection\s+%s\s*$" % section, line):
                    self.lines.insert(i + 1, "  set %s = %s" % (key, new))
                    return
            self.lines += ["subsection " + section,
                           "  set %s = %s" % (key, new), "end"]

    def put_json(self, section, key, new):
        pair = '"%s": "%s"' % (key, new.replace("\\", "\\\\"))
        if section is not None:
            for i, line in enumerate(self.lines):
                m = re.search(r'"%s"\s*:\s*\{' % section, line)
                if m:
                    rest = line[m.end():]
                    self.lines[i] = (line[:m.end()] + " " + pair +
                                     ("" if rest.strip().startswith("}")
                                      else ",") + rest)
                    return
            pair = '"%s": { %s }' % (section, pair)
        self.lines.insert(1, "  " + pair + ",")


def shown(text, width=40):
    """A value for a description: quoted, long ones abbreviated."""
    text = text.replace("\t", "\\t")
    if len(text) > width:
        text = "%s...<%d chars>" % (text[:8], len(text))
    return "'" + text + "'"


def pick_entry(case, rng, key_pattern=None, value_pattern=None):
    entries = [e for e in case.entries()
               if (key_pattern is None or re.search(key_pattern, e[1]))
               and (value_pattern is None
                    or re.search(value_pattern, case.value(e)))]
    return rng.choice(entries) if entries else None


def mutate_delete_line(case, rng):
    i = rng.choice(case.code_lines())
    line = case.lines.pop(i)
    return "delete line %d %s" % (i + 1, shown(line.strip(), 60))


def mutate_duplicate_line(case, rng):
    i = rng.choice(case.code_lines())
    case.lines.insert(i + 1, case.lines[i])
    return "duplicate line %d %s" % (i + 1, shown(case.lines[i].strip(), 60))


def mutate_swap_lines(case, rng):
    lines = case.code_lines()
    if len(lines) < 2:
        return None
    i, j = sorted(rng.sample(lines, 2))
    case.lines[i], case.lines[j] = case.lines[j], case.lines[i]
    return "swap lines %d and %d" % (i + 1, j + 1)


def mutate_number(case, rng):
    entry = pick_entry(case, rng, value_pattern=NUMBER.pattern)
    if entry is None:
        return None
    value = case.value(entry)
    numbers = list(NUMBER.finditer(value))
    m = rng.choice(numbers)
    new = rng.choice(ODD_NUMBERS)
    case.set_value(entry, value[:m.start()] + new + value[m.end():])
    return "number '%s' %s: %s -> %s" % (entry[1], shown(value), m.group(),
                                         shown(new))


def mutate_empty_value(case, rng):
    entry = pick_entry(case, rng, value_pattern=r"\S")
    if entry is None:
        return None
    old = case.value(entry)
    case.set_value(entry, "")
    return "empty '%s' (was %s)" % (entry[1], shown(old))


def mutate_trailing_junk(case, rng):
    entry = pick_entry(case, rng)
    if entry is None:
        return None
    junk = rng.choice(JUNK)
    case.set_value(entry, case.value(entry) + junk)
    return "junk '%s' += %s" % (entry[1], shown(junk))


def mutate_ids(case, rng):
    entry = pick_entry(case, rng, r"ids|Interfaces|Block materials|Point "
                       r"supports|Joint sets|degrees|levels|Generator "
                       r"arguments|Circular", r"\d")
    if entry is None:
        return None
    value = case.value(entry)
    parts = value.split(",")
    how = rng.choice(("duplicate", "swap", "reverse", "odd id"))
    if how == "duplicate":
        new = value + "," + rng.choice(parts)
    elif how == "swap" and len(parts) > 1:
        a, b = sorted(rng.sample(range(len(parts)), 2))
        parts[a], parts[b] = parts[b], parts[a]
        new = ",".join(parts)
    elif how == "reverse" and ":" in value:
        new = re.sub(r"(\w+)\s*:\s*(\w+)", r"\2:\1", value, count=1)
    else:
        how = "odd id"
        m = rng.choice(list(INTEGER.finditer(value)))
        new = value[:m.start()] + rng.choice(ODD_IDS) + value[m.end():]
    case.set_value(entry, new)
    return "ids '%s' %s: %s -> %s" % (entry[1], how, shown(value),
                                       shown(new))


def mutate_function(case, rng):
    entry = pick_entry(case, rng, r"Function|Variable names")
    if entry is None:
        return None
    key = entry[1]
    if key == "Function expression" and case.ext == ".prm" and \
            rng.random() < 0.4:
        sibling = rng.choice(("Function constants", "Variable names"))
        new = rng.choice(CONSTANTS if sibling == "Function constants"
                         else VARIABLES)
        line = "%sset %s = %s" % (re.match(r"\s*", case.lines[entry[0]])
                                  .group(), sibling, new)
        case.lines.insert(entry[0] + 1, line)
        return "function insert '%s' = %s at line %d" % (
            sibling, shown(new), entry[0] + 2)
    choices = (CONSTANTS if "constants" in key else
               VARIABLES if "Variable" in key else EXPRESSIONS)
    old = case.value(entry)
    new = rng.choice(choices)
    case.set_value(entry, new)
    return "function '%s' %s -> %s" % (key, shown(old), shown(new))


def mutate_output(case, rng):
    key, section, choices = rng.choice(
        (("Directory", "Output", DIRECTORIES),
         ("Base name", "Output", BASE_NAMES),
         ("Table file", "Order study", TABLE_FILES)))
    if key == "Table file" and not any("order study" in line
                                       for line in case.lines):
        key, choices = "Directory", DIRECTORIES
        section = "Output"
    new = rng.choice(choices)
    case.put(section, key, new)
    case.extra["afile"] = b"a regular file, not a folder\n"
    return "output '%s' = %s" % (key, shown(new))


def mutate_dimension(case, rng):
    old = [case.value(e) for e in case.entries() if e[1] == "Dimension"]
    new = rng.choice([d for d in DIMENSIONS if d not in old[:1]])
    case.put(None, "Dimension", new)
    return "Dimension = %s (was %s)" % (shown(new),
                                        shown(old[0]) if old else "2")


def mutate_unbalance(case, rng):
    if case.ext == ".json":
        return mutate_unbalance_json(case, rng)
    ends = [i for i, line in enumerate(case.lines)
            if line.strip().lower() == "end"]
    how = rng.choice(("drop end", "extra end", "open subsection",
                      "early end", "misspelt subsection"))
    at = rng.randrange(len(case.lines) + 1)
    if how == "drop end" and ends:
        i = rng.choice(ends)
        del case.lines[i]
        return "unbalance: drop 'end' of line %d" % (i + 1)
    if how == "open subsection":
        case.lines.insert(at, "subsection Mesh")
        return "unbalance: 'subsection Mesh' at line %d" % (at + 1)
    if how == "misspelt subsection":
        subs = [i for i, line in enumerate(case.lines)
                if line.strip().startswith("subsection")]
        if subs:
            i = rng.choice(subs)
            case.lines[i] = case.lines[i].replace("subsection",
                                                  "subsectoin", 1)
            return "unbalance: 'subsectoin' at line %d" % (i + 1)
    if how == "early end":
        case.lines.insert(at, "end")
        return "unbalance: 'end' at line %d" % (at + 1)
    case.lines.append("end")
    return "unbalance: extra 'end' at the end"


def mutate_unbalance_json(case, rng):
    braces = [i for i, line in enumerate(case.lines) if "{" in line
              or "}" in line]
    i = rng.choice(braces)
    old = case.lines[i]
    case.lines[i] = rng.choice((old.replace("{", "", 1),
                                old.replace("}", "", 1), old + "}",
                                old.replace("{", "[", 1)))
    return "unbalance JSON line %d %s" % (i + 1, shown(old.strip(), 30))


def mutate_include(case, rng):
    if case.ext == ".json":
        return None
    target = rng.choice(("input.prm", "missing.prm", ".", "mesh.msh",
                         "afile", "", "sub/../input.prm"))
    at = rng.randrange(len(case.lines) + 1)
    case.lines.insert(at, "include " + target)
    case.extra["afile"] = b"set Dimension = 2\n"
    return "include %s at line %d" % (shown(target), at + 1)


def mutate_mesh_file(case, rng):
    if case.mesh is None:
        return None
    new = rng.choice(MESH_FILES)
    case.put("Mesh", "Mesh file", new)
    case.extra["afile"] = b"not a mesh\n"
    return "mesh file = %s" % shown(new)


def mesh_lines(case):
    return case.mesh.decode("latin-1").split("\n")


def set_mesh_lines(case, lines):
    case.mesh = bytearray("\n".join(lines).encode("latin-1"))


def section_lines(lines, name):
    """Indices of the data lines of $name (after its count line)."""
    try:
        start = lines.index("$" + name)
        end = lines.index("$End" + name)
    except ValueError:
        return []
    return list(range(start + 2, end))


def mutate_mesh_truncate(case, rng):
    if case.mesh is None:
        return None
    at = rng.randrange(len(case.mesh))
    total = len(case.mesh)
    del case.mesh[at:]
    return "mesh truncated at byte %d of %d" % (at, total)


def mutate_mesh_flip(case, rng):
    if case.mesh is None:
        return None
    flips = []
    for _ in range(rng.randint(1, 8)):
        at, bits = rng.randrange(len(case.mesh)), rng.randint(1, 255)
        case.mesh[at] ^= bits
        flips.append("%d^%d" % (at, bits))
    return "mesh bytes flipped " + ",".join(flips)


def mutate_mesh_drop_elements(case, rng):
    lines = mesh_lines(case) if case.mesh is not None else []
    elements = section_lines(lines, "Elements")
    if not elements:
        return None
    dropped = sorted(rng.sample(elements, min(len(elements),
                                              rng.randint(1, 5))))
    set_mesh_lines(case, [line for i, line in enumerate(lines)
                          if i not in dropped])
    return "mesh element lines dropped " + ",".join(str(i + 1)
                                                    for i in dropped)


def mutate_mesh_number(case, rng):
    lines = mesh_lines(case) if case.mesh is not None else []
    name = rng.choice(("Nodes", "Elements"))
    rows = section_lines(lines, name)
    if not rows:
        return None
    i = rng.choice(rows)
    fields = lines[i].split(" ")
    # Node: number x y z; element: number type ntags tags... nodes.
    column = (rng.randint(1, 3) if name == "Nodes"
              else rng.choice((1, 2, len(fields) - 1)))
    old = fields[column]
    fields[column] = (rng.choice(("1", "2", "4", "5", "15", "99", "0"))
                      if name == "Elements" and column == 1
                      else rng.choice(MESH_NUMBERS))
    lines[i] = " ".join(fields)
    set_mesh_lines(case, lines)
    return "mesh %s line %d field %d: %s -> %s" % (
        name.lower(), i + 1, column, shown(old), shown(fields[column]))


MUTATIONS = (
    ("delete", mutate_delete_line),
    ("duplicate", mutate_duplicate_line),
    ("swap", mutate_swap_lines),
    ("number", mutate_number),
    ("number", mutate_number),
    ("empty", mutate_empty_value),
    ("junk", mutate_trailing_junk),
    ("ids", mutate_ids),
    ("function", mutate_function),
    ("function", mutate_function),
    ("output", mutate_output),
    ("dimension", mutate_dimension),
    ("unbalance", mutate_unbalance),
    ("include", mutate_include),
    ("mesh-file", mutate_mesh_file),
    ("mesh-truncate", mutate_mesh_truncate),
    ("mesh-flip", mutate_mesh_flip),
    ("mesh-drop", mutate_mesh_drop_elements),
    ("mesh-number", mutate_mesh_number),
    ("mesh-number", mutate_mesh_number),
)


class Plan:
    """Run 'index': its seed, its case, the kinds and descriptions of its
    mutations, or for a fault run the delay of the SIGTERM."""

    def __init__(self, campaign_seed, index, seeds, mutated=True):
        rng = random.Random("mbfem-mutation-campaign/%d/%d"
                            % (campaign_seed, index))
        self.index = index
        self.seed = rng.choice(seeds)
        self.case = Case(self.seed)
        self.fault = mutated and index % FAULT_EVERY == FAULT_EVERY // 2
        self.delay = round(rng.uniform(0.05, 2.), 3) if self.fault else None
        self.kinds, self.descriptions = [], []
        if not mutated:
            self.descriptions = ["unmutated"]
            return
        if self.fault:
            self.kinds = ["fault"]
            self.descriptions = ["fault: SIGTERM after %.3f s" % self.delay]
            return
        for _ in range(rng.choice((1, 1, 2))):
            self.mutate(rng)

    def mutate(self, rng):
        for _ in range(50):
            kind, mutation = rng.choice(MUTATIONS)
            description = mutation(self.case, rng)
            if description is not None:
                self.kinds.append(kind)
                self.descriptions.append(description)
                return

    def description(self):
        return " + ".join(self.descriptions)


# -- Running ---------------------------------------------------------------

class Result:
    def __init__(self):
        self.returncode = None
        self.hang = False
        self.signalled = False       # we sent SIGTERM (fault run)
        self.stdout = self.stderr = ""
        self.seconds = 0.
        self.escaped = []
        self.verdict, self.sub, self.message = "OK", "", ""


def write_case(folder, case):
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    with open(os.path.join(folder, case.input_name()), "w") as f:
        f.write("\n".join(case.lines) + "\n")
    if case.mesh is not None:
        with open(os.path.join(folder, "mesh.msh"), "wb") as f:
            f.write(case.mesh)
    for name, content in sorted(case.extra.items()):
        with open(os.path.join(folder, name), "wb") as f:
            f.write(content)


def stop(proc, grace):
    """SIGTERM, then SIGKILL to the process group after 'grace' s."""
    try:
        proc.send_signal(signal.SIGTERM)
        proc.wait(grace)
    except subprocess.TimeoutExpired:
        try:
            os.killpg(proc.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        proc.wait()
    except ProcessLookupError:
        pass


def snapshot(mbfem, work):
    """A copy of mbfem and of the libmbfem-lib.so beside it in WORK/bin,
    so that a rebuild during the campaign does not change (or, half
    written, break) the program under test; (path, environment)."""
    folder = os.path.join(work, "bin")
    os.makedirs(folder, exist_ok=True)
    copy = os.path.join(folder, "mbfem")
    shutil.copy2(mbfem, copy)
    environment = dict(os.environ, **ENVIRONMENT)
    library = os.path.join(os.path.dirname(mbfem), "libmbfem-lib.so")
    if os.path.exists(library):
        shutil.copy2(library, folder)
        environment["LD_LIBRARY_PATH"] = ":".join(
            [folder] + [p for p in [os.environ.get("LD_LIBRARY_PATH")] if p])
    return copy, environment


def start_process(args, folder, plan, out, err, session_base):
    """Popen, retried while the binary is busy or missing for a moment.
    Open MPI's session directory goes under 'session_base': singletons
    started at the same time under one user otherwise share
    /tmp/ompi.HOST.UID/jf.0, which the one that ends first may remove
    while another creates its own in it (it then fails to start)."""
    environment = dict(args.environment,
                       OMPI_MCA_orte_tmpdir_base=session_base)
    for attempt in range(10):
        try:
            return subprocess.Popen([args.mbfem, plan.case.input_name()],
                                    cwd=folder, stdout=out, stderr=err,
                                    stdin=subprocess.DEVNULL,
                                    env=environment,
                                    start_new_session=True)
        except OSError:
            if attempt == 9:
                raise
            time.sleep(2)


def execute(args, folder, plan, memory_limit):
    """Runs mbfem in 'folder'; fills a Result (no verdict yet)."""
    result = Result()
    start = time.time()
    session_base = tempfile.mkdtemp(prefix="mbfem-ompi-")
    try:
        return run_and_read(args, folder, plan, memory_limit, result, start,
                            session_base)
    finally:
        shutil.rmtree(session_base, ignore_errors=True)


def run_and_read(args, folder, plan, memory_limit, result, start,
                 session_base):
    """execute()'s run, its wait and what it left."""
    with open(os.path.join(folder, "stdout.txt"), "w") as out, \
            open(os.path.join(folder, "stderr.txt"), "w") as err:
        proc = start_process(args, folder, plan, out, err, session_base)
        limit_memory(proc.pid, memory_limit)
        try:
            if plan.fault:
                try:
                    proc.wait(plan.delay)
                except subprocess.TimeoutExpired:
                    result.signalled = True
                    proc.send_signal(signal.SIGTERM)
                    proc.wait(FAULT_GRACE)
            else:
                proc.wait(args.timeout)
        except subprocess.TimeoutExpired:
            result.hang = True
            stop(proc, KILL_GRACE)
    result.seconds = time.time() - start
    result.returncode = proc.returncode
    if proc.returncode < 0:
        # Open MPI's helper (orted, in a session of its own) writes its
        # complaint about a killed run to the same stderr a moment later.
        time.sleep(ORTED_GRACE)
    result.stdout = read_text(os.path.join(folder, "stdout.txt"))
    result.stderr = read_text(os.path.join(folder, "stderr.txt"))
    result.escaped = escaped_files(start)
    return result


def limit_memory(pid, gigabytes):
    """Caps the address space so that a huge allocation fails in mbfem
    instead of exhausting the machine."""
    if gigabytes <= 0:
        return
    size = int(gigabytes * 2**30)
    try:
        resource.prlimit(pid, resource.RLIMIT_AS, (size, size))
        resource.prlimit(pid, resource.RLIMIT_CORE, (0, 0))
    except (OSError, ValueError):
        pass


def escaped_files(start):
    """Result files written in / since 'start' (an empty output folder
    must not put them there)."""
    found = []
    for entry in sorted(os.scandir("/"), key=lambda e: e.name):
        try:
            if entry.is_file(follow_symlinks=False) and \
                    entry.stat().st_mtime >= start - 1 and \
                    re.search(r"\.(pvd|vtu|csv|part)$", entry.name):
                found.append(entry.path)
        except OSError:
            pass
    return found


def read_text(path):
    try:
        with open(path, "rb") as f:
            return f.read().decode("utf-8", "replace")
    except OSError:
        return ""


def run_files(folder):
    """Relative paths of all files in the run folder, sorted."""
    found = []
    for root, dirs, files in os.walk(folder):
        dirs.sort()
        for name in sorted(files):
            found.append(os.path.relpath(os.path.join(root, name), folder))
    return found


# -- Verdicts --------------------------------------------------------------

def error_message(stderr):
    """mbfem's message (after 'mbfem: error', its lines joined, since
    deal.II's messages begin with 'Line <N> of file <F>:'), or a
    'mbfem: ...' line, or the last line of stderr."""
    lines = [line.strip() for line in stderr.splitlines()]
    for i, line in enumerate(lines):
        if line == "mbfem: error":
            rest = [text for text in lines[i + 1:] if text]
            if "Aborting." in rest:
                rest = rest[:rest.index("Aborting.")]
            return " ".join(rest)
    for line in lines:
        if line.startswith("mbfem:"):
            return line
    rest = [line for line in lines if line]
    return rest[-1] if rest else ""


def has_message(stderr):
    lines = [line.strip() for line in stderr.splitlines()]
    if "mbfem: error" not in lines:
        return False
    return error_message(stderr) not in ("", "Aborting.")


def raw_text(stderr):
    """The name of the first raw pattern stderr matches, or None."""
    for name, pattern in RAW:
        if pattern.search(stderr):
            return name
    return None


def signal_name(number):
    try:
        return signal.Signals(number).name
    except ValueError:
        return "signal %d" % number


def nonfinite_output(folder, files, stdout):
    """Where a nan or inf is written as a number, or None."""
    if NONFINITE.search(stdout):
        return "stdout"
    for name in files:
        path = os.path.join(folder, name)
        if name.endswith(".csv") and NONFINITE.search(read_text(path)):
            return name
        if name.endswith(".vtu") and vtu_nonfinite(read_text(path)):
            return name
    return None


def vtu_nonfinite(text):
    """Whether a float DataArray of a VTU file (ASCII, or deal.II's
    base64 zlib-compressed binary) holds nan or inf."""
    compressed = "vtkZLibDataCompressor" in text
    for attributes, body in re.findall(r"<DataArray([^>]*)>(.*?)</DataArray>",
                                       text, re.S):
        kind = re.search(r'type="(Float32|Float64)"', attributes)
        if not kind:
            continue
        if 'format="ascii"' in attributes:
            if NONFINITE.search(body):
                return True
            continue
        try:
            data = decode_binary(body.strip(), compressed)
        except (ValueError, zlib.error, struct.error):
            continue
        values = array.array("f" if kind.group(1) == "Float32" else "d")
        values.frombytes(data[:len(data) - len(data) % values.itemsize])
        if not all(math.isfinite(v) for v in values):
            return True
    return False


def decode_binary(body, compressed):
    """The bytes of a binary VTU DataArray (UInt32 headers)."""
    if not compressed:
        raw = base64.b64decode(body)
        return raw[4:4 + struct.unpack("<I", raw[:4])[0]]
    blocks = struct.unpack("<I", base64.b64decode(body[:8])[:4])[0]
    header_chars = 4 * ((12 + 4 * blocks + 2) // 3)
    header = base64.b64decode(body[:header_chars])
    sizes = struct.unpack("<%dI" % blocks, header[12:12 + 4 * blocks])
    packed = base64.b64decode(body[header_chars:])
    data, offset = b"", 0
    for size in sizes:
        data += zlib.decompress(packed[offset:offset + size])
        offset += size
    return data


def pvd_missing(folder, files):
    """The first file a .pvd names that is not there, or None."""
    for name in files:
        if not name.endswith(".pvd"):
            continue
        text = read_text(os.path.join(folder, name))
        if "</VTKFile>" not in text:
            return name + " (incomplete)"
        for target in sorted(set(re.findall(r'file="([^"]*)"', text))):
            path = os.path.join(folder, os.path.dirname(name), target)
            if not os.path.isfile(path):
                return target
    return None


def classify(result, folder):
    """Sets result.verdict, .sub and .message."""
    rc, stderr = result.returncode, result.stderr
    ours = result.signalled
    files = run_files(folder)
    result.message = error_message(stderr)
    checks = (
        ("HANG", result.hang),
        ("CRASH", rc < 0 and not (ours and rc == -signal.SIGTERM)),
        ("CRASH", rc >= 128 and not (ours and rc == 128 + signal.SIGTERM)),
        ("CRASH", any(os.path.basename(f).startswith("core")
                      for f in files)),
        ("ESCAPE", bool(result.escaped)),
        ("UNKNOWN", "unknown error" in stderr),
        ("RAW", raw_text(stderr) is not None),
        ("NOMSG", 0 < rc < 128 and not has_message(stderr)),
        ("PART", any(f.endswith(".part") for f in files)),
        ("PVD", pvd_missing(folder, files) is not None),
        ("NONFINITE_EXIT0",
         rc == 0 and nonfinite_output(folder, files, result.stdout)),
    )
    for verdict, failed in checks:
        if failed:
            result.verdict = verdict
            break
    result.sub = detail(result, folder, files)


def detail(result, folder, files):
    """What makes the verdict (for the line), or the OK sub-count."""
    rc, verdict = result.returncode, result.verdict
    if verdict == "HANG":
        return "fault run not ended" if result.signalled else "timeout"
    if verdict == "CRASH":
        return signal_name(-rc) if rc < 0 else "exit %d" % rc
    if verdict == "ESCAPE":
        return ",".join(result.escaped)
    if verdict == "RAW":
        return raw_text(result.stderr)
    if verdict == "PART":
        return [f for f in files if f.endswith(".part")][0]
    if verdict == "PVD":
        return pvd_missing(folder, files)
    if verdict == "NONFINITE_EXIT0":
        return nonfinite_output(folder, files, result.stdout)
    if verdict == "NOMSG":
        return "exit %d" % rc
    if rc < 0:
        return "killed by our SIGTERM (no handler yet)"
    if rc >= 128:
        return "stopped by our SIGTERM (%d)" % rc
    return {0: "exit 0", 1: "refused (1)", 2: "contact verdict (2/3/4)",
            3: "contact verdict (2/3/4)",
            4: "contact verdict (2/3/4)"}.get(rc, "exit %d" % rc)


def run_plan(args, plan):
    folder = os.path.join(args.work, "%04d" % plan.index)
    write_case(folder, plan.case)
    result = execute(args, folder, plan, args.memory_limit)
    classify(result, folder)
    return result


# -- Output ----------------------------------------------------------------

def exit_text(result):
    if result.hang:
        return "timeout"
    rc = result.returncode
    return signal_name(-rc) if rc < 0 else str(rc)


def clean(text, args):
    """Paths out of a message (in test mode)."""
    for path, name in ((os.path.abspath(args.work), "WORK"),
                       (SOURCE, "SOURCE")):
        text = text.replace(path, name)
    return text


def run_line(plan, result, args):
    message = result.message
    if args.test:
        message = clean(message, args)
    message = message[:120]
    verdict = result.verdict
    if result.verdict != "OK":
        verdict += " (%s)" % result.sub
    if plan.fault and args.test:
        text = "%4d %s | %s | %s" % (plan.index, plan.seed.name,
                                     plan.description(), result.verdict)
    else:
        text = "%4d %s | %s | %s | exit %s | %s" % (
            plan.index, plan.seed.name, plan.description(), verdict,
            exit_text(result), message)
    if not args.test:
        text += " | %.1f s" % result.seconds
    return text


def sub_count(plan, result, args):
    if plan.fault and args.test:
        return "fault run"
    return result.sub


def summary(plans, results, args, seconds):
    counts = {v: 0 for v in VERDICTS}
    subs, kinds = {}, {}
    for plan, result in zip(plans, results):
        counts[result.verdict] += 1
        if result.verdict == "OK":
            key = sub_count(plan, result, args)
            subs[key] = subs.get(key, 0) + 1
        for kind in sorted(set(plan.kinds)):
            total, bad = kinds.get(kind, (0, 0))
            kinds[kind] = (total + 1, bad + (result.verdict != "OK"))
    n_fault = sum(plan.fault for plan in plans)
    lines = ["", "summary (seed %d, %d runs, %d of them fault runs%s):" % (
        args.seed, len(plans), n_fault,
        "" if seconds is None else ", %.0f s" % seconds)]
    for verdict in VERDICTS:
        lines.append("  %-16s %5d" % (verdict, counts[verdict]))
    for key in sorted(subs):
        lines.append("    OK, %-38s %5d" % (key, subs[key]))
    lines.append("runs with a mutation of each kind, not OK of them:")
    for kind in sorted(kinds):
        lines.append("  %-14s %5d %5d" % ((kind,) + kinds[kind]))
    failed = sum(counts[v] for v in FAILING)
    lines.append("not OK: %d of %d" % (failed, len(plans)))
    return lines, failed == 0


def check_seeds(args, seeds):
    """Runs every seed unmutated: exit code, verdict and time."""
    failed = 0
    for seed in seeds:
        plan = Plan(args.seed, 0, [seed], mutated=False)
        folder = os.path.join(args.work, "seed-" + re.sub(r"\W", "_",
                                                          seed.name))
        write_case(folder, plan.case)
        result = execute(args, folder, plan, args.memory_limit)
        classify(result, folder)
        failed += result.verdict != "OK" or result.returncode != 0
        print("%-40s exit %s %s %5.1f s %s" % (
            seed.name, exit_text(result), result.verdict, result.seconds,
            result.message[:80]), flush=True)
    return 1 if failed else 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--mbfem", default=os.path.join(SOURCE, "build",
                                                        "mbfem"))
    parser.add_argument("--work", default="/tmp/mutation_campaign/runs")
    parser.add_argument("--count", type=int, default=1000)
    parser.add_argument("--seed", type=int, default=29)
    parser.add_argument("--timeout", type=float, default=60.)
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--memory-limit", type=float, default=6.,
                        help="address space of a run in GiB (0: none)")
    parser.add_argument("--only", default="",
                        help="run only these indices (comma-separated)")
    parser.add_argument("--test", action="store_true",
                        help="no times, no paths (stored output)")
    parser.add_argument("--list", action="store_true",
                        help="print the mutations, do not run")
    parser.add_argument("--check-seeds", action="store_true",
                        help="run the seeds unmutated")
    args = parser.parse_args()
    seeds = [Seed(name) for name in sorted(SEEDS)]
    plans = [Plan(args.seed, i, seeds) for i in range(args.count)]
    if args.only:
        wanted = set(int(i) for i in args.only.split(","))
        plans = [plan for plan in plans if plan.index in wanted]
    if args.list:
        for plan in plans:
            print("%4d %s | %s" % (plan.index, plan.seed.name,
                                   plan.description()))
        return 0
    if not os.access(args.mbfem, os.X_OK):
        sys.exit("--mbfem: %s is not an executable" % args.mbfem)
    args.work = os.path.abspath(args.work)
    os.makedirs(args.work, exist_ok=True)
    args.mbfem, args.environment = snapshot(os.path.abspath(args.mbfem),
                                            args.work)
    if args.check_seeds:
        return check_seeds(args, seeds)
    start = time.time()
    with ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        results = []
        for plan, result in zip(plans, pool.map(
                lambda p: run_plan(args, p), plans)):
            print(run_line(plan, result, args), flush=True)
            results.append(result)
    lines, passed = summary(plans, results, args,
                            None if args.test else time.time() - start)
    print("\n".join(lines))
    if not args.test:
        print("work folder:", args.work)
    return 0 if passed else 1


if __name__ == "__main__":
    sys.exit(main())
