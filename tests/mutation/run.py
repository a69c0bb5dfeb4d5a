#!/usr/bin/env python3
"""Grade machine-made mutants of the solutions, and table how many the grader kills.

    cmake --build --preset test --target mutation_07     # one chapter (or `mutation`: all ten)

which runs, in the test build,

    python3 tests/mutation/run.py --build build/test --chapters 07 [--jobs 2] [--limit N]

For each mutant of chapter NN's SOLUTION blocks (operators.py): compile it as the chapter's
solution; drop it when it does not compile or compiles to the solution's own object code; link it
into chapter NN's grader (the other chapters stay the solutions'); run the mutant's own exercise's
cases, and, when they all pass, the chapter's other cases. A mutant is killed when a case loses
points (or the grader crashes, or runs past the time limit); killed in its own exercise when one of
that exercise's cases does. A survivor is a gap in the grader, unless equivalent.txt argues that no
input can tell it from the solution.

Writes build/mutation/NN_name.json (every mutant's fate) and build/mutation/table.md (every chapter
run so far), and prints the table and each survivor.
"""

import argparse
import concurrent.futures as futures
import glob
import hashlib
import json
import os
import shlex
import shutil
import subprocess
import sys
import time

try:
    import clang.cindex  # noqa: F401  (python3-clang)
except ImportError:
    # A Python of its own (pyenv, a venv) does not see Debian's python3-clang: use the system's.
    if os.path.exists("/usr/bin/python3") and os.path.realpath(sys.executable) != os.path.realpath("/usr/bin/python3"):
        os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
    sys.exit("run.py: needs libclang's Python bindings (Debian: apt-get install python3-clang)")

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from operators import Generator  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE_DIR = os.path.dirname(os.path.dirname(HERE))


def read_equivalents(path):
    """id -> (exercise, why it is equivalent), from `id | exercise | change | why` lines."""
    equivalent = {}
    if not os.path.exists(path):
        return equivalent
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            fields = [x.strip() for x in line.split("|")]
            if len(fields) < 4 or not fields[3]:
                sys.exit(f"{path}:{number}: an equivalent mutant is `id | exercise | change | why`, got: {line}")
            equivalent[fields[0]] = (fields[1], fields[3])
    return equivalent


def ninja_commands(build, target):
    """The compile command of the mutation source and the grader's link command, as Ninja runs them."""
    out = subprocess.run(["ninja", "-C", build, "-t", "commands", target], check=True, capture_output=True, text=True).stdout
    return out.splitlines()


class Chapter:
    def __init__(self, build, chapter, jobs):
        self.build = os.path.abspath(build)
        self.chapter = chapter
        self.nn = chapter[:2]
        self.source = os.path.join(self.build, "tests", "mutation", chapter + ".cpp")
        target = f"grade_mutation_{self.nn}"
        subprocess.run(["cmake", "--build", self.build, "--target", target], check=True, stdout=subprocess.DEVNULL)
        lines = ninja_commands(self.build, target)
        compile_lines = [x for x in lines if " -c " in x and x.rstrip().endswith(self.source)]
        if not compile_lines:
            sys.exit(f"run.py: no compile command for {self.source} in {self.build} (a Ninja build of the test preset?)")
        # Ninja's own command lines, run by a shell with the source, object and grader swapped for a slot's.
        compile_args = shlex.split(compile_lines[0])
        self.object = compile_args[compile_args.index("-o") + 1]
        self.compile = compile_lines[0]
        for flag in ("-MT", "-MF"):
            if flag in compile_args:
                i = compile_args.index(flag)
                self.compile = self.compile.replace(f" {flag} {compile_args[i + 1]}", "")
        self.compile = self.compile.replace(" -MD ", " ")
        self.link = lines[-1]
        link_args = shlex.split(self.link)
        self.grader = link_args[link_args.index("-o") + 1]
        # The include flags libclang needs to parse the solution as the compiler does.
        parse_args = ["-std=c++17"]
        for i, a in enumerate(compile_args):
            if a.startswith(("-I", "-D")) and len(a) > 2:
                parse_args.append(a)
            elif a in ("-I", "-isystem", "-D"):
                parse_args += [a, compile_args[i + 1]]
        solution = os.path.join(SOURCE_DIR, "solutions", chapter + ".cpp")
        self.generator = Generator(solution, parse_args)
        self.text = self.generator.text
        self.slots = [os.path.join(self.build, "mutation", chapter, f"slot{k}") for k in range(jobs)]
        self.baseline = {}
        for slot in self.slots:
            os.makedirs(slot, exist_ok=True)
            ok, digest = self.compile_in(slot, self.text)
            if not ok:
                sys.exit(f"run.py: the solution of {chapter} does not compile in {slot}:\n{digest}")
            self.baseline[slot] = digest
        # The grader's time on the solution sets the limit past which a mutant counts as looping.
        start = time.monotonic()
        self.link_in(self.slots[0])
        run = subprocess.run([os.path.join(self.slots[0], "grade"), "--out", os.devnull], cwd=self.slots[0],
                             capture_output=True, text=True)
        if run.returncode != 0:
            sys.exit(f"run.py: the solution of {chapter} does not score full points:\n{run.stdout[-2000:]}")
        self.time_limit = 5 * (time.monotonic() - start) + 20

    def compile_in(self, slot, text):
        path = os.path.join(slot, self.chapter + ".cpp")
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)
        command = self.compile.replace(f" -o {self.object} ", f" -o {shlex.quote(os.path.join(slot, 'mutant.o'))} ")
        command = command.replace(f" -c {self.source}", f" -c {shlex.quote(path)}")
        r = subprocess.run(command, shell=True, cwd=self.build, capture_output=True, text=True)
        if r.returncode != 0:
            return False, r.stderr
        with open(os.path.join(slot, "mutant.o"), "rb") as f:
            return True, hashlib.sha1(f.read()).hexdigest()

    def link_in(self, slot):
        command = self.link.replace(f" {self.object} ", f" {shlex.quote(os.path.join(slot, 'mutant.o'))} ")
        command = command.replace(f" -o {self.grader} ", f" -o {shlex.quote(os.path.join(slot, 'grade'))} ")
        return subprocess.run(command, shell=True, cwd=self.build, capture_output=True, text=True).returncode == 0

    def grade_in(self, slot, spec):
        """The exercises whose cases lost points (or 'crash'/'timeout'), running the cases of `spec`."""
        results = os.path.join(slot, "results")
        if os.path.exists(results):
            os.remove(results)
        pictures = os.path.join(slot, "pictures")
        try:
            r = subprocess.run([os.path.join(slot, "grade"), spec, "--results", results, "--artifacts", pictures,
                                "--out", os.devnull], cwd=slot, capture_output=True, timeout=self.time_limit)
        except subprocess.TimeoutExpired:
            return {"timeout"}
        lost = set()
        if os.path.exists(results):
            with open(results, encoding="utf-8", errors="replace") as f:
                for line in f:
                    fields = line.rstrip("\n").split("\t")
                    if len(fields) >= 3 and fields[1] != fields[2]:
                        lost.add(fields[0])
        if r.returncode < 0 or (r.returncode != 0 and not lost):
            lost.add("crash")
        return lost

    def fate(self, slot, mutant):
        ok, digest = self.compile_in(slot, mutant.apply(self.text))
        if not ok:
            return {"fate": "does not compile"}
        if digest == self.baseline[slot]:
            return {"fate": "same object code"}
        if not self.link_in(slot):
            return {"fate": "does not compile"}
        own = self.grade_in(slot, f"[{mutant.exercise}]")
        if own:
            where = sorted(own)
            return {"fate": "killed", "own": True, "lost": where}
        elsewhere = self.grade_in(slot, f"~[{mutant.exercise}]")
        if elsewhere:
            return {"fate": "killed", "own": False, "lost": sorted(elsewhere)}
        return {"fate": "survived"}


def run_chapter(build, chapter, jobs, limit, sample, equivalent, out_dir):
    c = Chapter(build, chapter, jobs)
    mutants = c.generator.mutants()
    if sample:
        # The ids are hashes: the least N are a random sample, and the same one while the lines stay.
        mutants = sorted(sorted(mutants, key=lambda m: m.id)[:sample], key=lambda m: m.start)
        limit = sample
    elif limit:
        mutants = mutants[:limit]
    print(f"{chapter}: {len(mutants)} mutants, {jobs} at a time, {c.time_limit:.0f} s a run at most", flush=True)
    free = list(c.slots)
    records = []

    def one(mutant):
        slot = free.pop()
        try:
            record = c.fate(slot, mutant)
        finally:
            free.append(slot)
        record.update(id=mutant.id, exercise=mutant.exercise, operator=mutant.operator, line=mutant.line,
                      change=mutant.describe())
        if record["fate"] == "survived" and mutant.id in equivalent:
            record["fate"] = "equivalent"
            record["why"] = equivalent[mutant.id][1]
        return record

    start = time.monotonic()
    with futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        for n, record in enumerate(pool.map(one, mutants), 1):
            records.append(record)
            if record["fate"] == "survived":
                print(f"  survived {record['id']} {record['exercise']} line {record['line']}: {record['change']}", flush=True)
            if n % 25 == 0:
                print(f"  {n}/{len(mutants)} in {time.monotonic() - start:.0f} s", flush=True)
    ids = {m.id for m in mutants}
    stale = [] if limit else sorted(i for i, (e, _) in equivalent.items() if e[:2] == c.nn and i not in ids)
    with open(os.path.join(out_dir, chapter + ".json"), "w", encoding="utf-8") as f:
        json.dump({"chapter": chapter, "seconds": round(time.monotonic() - start), "mutants": records,
                   "limited": bool(limit), "sample": sample}, f, indent=1)
    return stale


def table(out_dir):
    """Per exercise: generated, dropped (no compile, same code), killed (own exercise), equivalent, surviving."""
    rows = []
    total = dict(generated=0, dropped=0, killed=0, own=0, equivalent=0, survived=0)
    lines = ["| exercise | generated | dropped | killed | in its own cases | equivalent | surviving | killed of non-equivalent |",
             "|---|---|---|---|---|---|---|---|"]
    for path in sorted(glob.glob(os.path.join(out_dir, "[0-9][0-9]_*.json"))):
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
        per = {}
        for m in data["mutants"]:
            e = per.setdefault(m["exercise"], dict(generated=0, dropped=0, killed=0, own=0, equivalent=0, survived=0))
            e["generated"] += 1
            if m["fate"] in ("does not compile", "same object code"):
                e["dropped"] += 1
            elif m["fate"] == "killed":
                e["killed"] += 1
                e["own"] += 1 if m.get("own") else 0
            elif m["fate"] == "equivalent":
                e["equivalent"] += 1
            else:
                e["survived"] += 1
        chapter_total = dict(generated=0, dropped=0, killed=0, own=0, equivalent=0, survived=0)
        for exercise in sorted(per):
            e = per[exercise]
            lines.append(row(exercise, e))
            for k in chapter_total:
                chapter_total[k] += e[k]
        part = f" (a sample of {data['sample']})" if data.get("sample") else (" (limited)" if data.get("limited") else "")
        lines.append(row(f"**{data['chapter']}**{part}", chapter_total))
        for k in total:
            total[k] += chapter_total[k]
    lines.append(row("**all**", total))
    return "\n".join(lines) + "\n"


def row(name, e):
    live = e["killed"] + e["survived"]
    share = f"{100.0 * e['killed'] / live:.0f}%" if live else "-"
    return (f"| {name} | {e['generated']} | {e['dropped']} | {e['killed']} | {e['own']} | {e['equivalent']} | "
            f"{e['survived']} | {share} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", required=True, help="the test preset's build folder (build/test)")
    parser.add_argument("--chapters", default="all", help="01,07 or all")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--limit", type=int, default=0, help="only the first N mutants of each chapter (a quick look)")
    parser.add_argument("--sample", type=int, default=0,
                        help="only N mutants of each chapter, the same N every run (those of the least ids)")
    args = parser.parse_args()
    chapters = sorted(os.path.basename(p)[:-4] for p in glob.glob(os.path.join(SOURCE_DIR, "solutions", "[0-9][0-9]_*.cpp")))
    if args.chapters != "all":
        wanted = args.chapters.split(",")
        unknown = [w for w in wanted if not any(c.startswith(w) for c in chapters)]
        if unknown:
            sys.exit(f"run.py: no chapter {', '.join(unknown)} (chapters: {', '.join(c[:2] for c in chapters)})")
        chapters = [c for c in chapters if any(c.startswith(w) for w in wanted)]
    equivalent = read_equivalents(os.path.join(HERE, "equivalent.txt"))
    out_dir = os.path.join(os.path.abspath(args.build), "mutation")
    os.makedirs(out_dir, exist_ok=True)
    stale = []
    for chapter in chapters:
        stale += run_chapter(args.build, chapter, args.jobs, args.limit, args.sample, equivalent, out_dir)
    text = table(out_dir)
    with open(os.path.join(out_dir, "table.md"), "w", encoding="utf-8") as f:
        f.write(text)
    print(text)
    print(f"table: {os.path.join(out_dir, 'table.md')}")
    for i in stale:
        print(f"equivalent.txt: {i} is no mutant of the solutions any more (its line changed): remove it")


if __name__ == "__main__":
    main()
