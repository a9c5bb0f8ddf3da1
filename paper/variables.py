#!/usr/bin/env python3
"""The report's numbers, generated from the results (issue 29; the pattern of showyourwork's
variables): every result paper.tex states is a macro written here from a result file, so a number
in the text cannot go stale. tests/paper/check_numbers.py fails when a result-like number appears
in paper.tex outside a macro.

    paper/variables.py --out FILE.tex --profile DIR [--select DIR] [--density JSON] [--radius JSON]
                       [--coarse JSON] [--nested DIR] [--chain DIR]

  --profile DIR   DATA/paper: tables/verdict.json, fits/*.json, averages/normal-*.dat
  --select DIR    DATA/select: the same on the held-out seeds where the rules chose
  --density JSON  the density rule's outcome (make density-rule)
  --radius JSON   the radius study's report (make radius)
  --coarse JSON   the coarse-grain study's summary (make coarse-grain)
  --nested DIR    data/nested: the self-consistency test's level reports (make nested), levels 1 and 0
  --chain DIR     data/three-decades: the three-decade chain's level reports that are committed, and
                  the medium's estimates (medium/estimate/seed-S.json) when they are

Macros are \\newcommand{\\vName}{text}; a file that is not given leaves its macros out, and
LaTeX then stops at the first one the text uses (a missing result is an error, never a stale one).
"""
import argparse
import glob
import json
import math
import os
import sys

SCENE = {"soft-solid": "Solid", "soft-soft": "Soft"}
KEY = {"a": "A", "b": "B", "c": "C", "delta": "Delta"}


def fail(msg):
    print(f"paper/variables.py: {msg}", file=sys.stderr)
    sys.exit(2)


def load(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        fail(f"{path}: {e}")


def sig(x, digits=3):
    """x to `digits` significant digits, as LaTeX math text (no trailing exponent noise)."""
    if x is None or (isinstance(x, float) and not math.isfinite(x)):
        return r"\text{---}"
    if x == 0:
        return "0"
    e = math.floor(math.log10(abs(x)))
    if -3 <= e < 5:
        d = max(0, digits - 1 - e)
        return f"{round(x, digits - 1 - e):.{d}f}"  # (round: an integer part longer than `digits` too)
    m = x / 10**e
    return rf"{m:.{digits - 1}f}\times10^{{{e}}}"


def pm(value, error):
    """value ± error, the error to two significant digits and the value to the same decimal."""
    if error is None or not math.isfinite(error) or error <= 0:
        return sig(value, 4)
    e = math.floor(math.log10(error)) - 1
    d = max(0, -e)
    if abs(value) >= 1e5 or abs(value) < 1e-3:
        return rf"({sig(value, 3)} \pm {sig(error, 2)})"
    return f"{value:.{d}f} \\pm {error:.{d}f}"


class Macros:
    def __init__(self):
        self.lines = []
        self.names = set()

    def add(self, name, text, source):
        if not name.isalpha():
            fail(f"macro name {name!r} is not letters only")
        if name in self.names:
            fail(f"macro \\{name} defined twice")
        self.names.add(name)
        self.lines.append(f"\\newcommand{{\\{name}}}{{{text}}}  % {source}")

    def math(self, name, text, source):
        self.add(name, f"\\ensuremath{{{text}}}", source)


def percent(x):
    return rf"{x * 100:+.0f}\,\%" if x is not None and math.isfinite(x) else r"\text{---}"


def profile_macros(m, d, prefix):
    """The verdict, the fit selection and Table 2's unit of one profile's results folder."""
    vpath = os.path.join(d, "tables", "verdict.json")
    v = load(vpath)
    for line in v["lines"]:
        base = f"v{prefix}{SCENE[line['scene']]}{'One' if line['table'] == 'table1' else 'Two'}{KEY[line['key']]}"
        m.math(base, pm(line["ours"], line["error"]) if line["ours"] is not None else r"\text{---}", vpath)
        m.math(base + "Dev", percent(line["deviation"]), vpath)
        m.add(base + "Status", line["status"], vpath)
    m.add(f"v{prefix}Reproduced", str(v["reproduced"]), vpath)
    m.add(f"v{prefix}Judged", str(v["judged"]), vpath)
    sel = v["selection"]
    m.add(f"v{prefix}FitChosen", sel["chosen"], vpath)
    m.add(f"v{prefix}FitIsProfiles", "yes" if sel["profile_fit_is_chosen"] else "no", vpath)
    for name, scenes in sel["candidates"].items():
        cname = "".join(ch for ch in name.title() if ch.isalpha())
        for scene, c in scenes.items():
            base = f"v{prefix}Cand{cname}{SCENE[scene]}"
            m.math(base + "Chi", sig(c["chi2_per_dof"], 3), vpath)
            m.math(base + "Runs", sig(c["runs_z"], 2) if c["runs_z"] is not None else r"\text{---}", vpath)
            m.math(base + "B", sig(c.get("b"), 3), vpath)
            m.math(base + "Delta", sig(c.get("delta"), 3), vpath)
            jb, b = c["jackknife_b"], c.get("b")
            m.math(base + "JackB", rf"{100 * jb / abs(b):.1f}\,\%" if jb is not None and b else r"\text{---}", vpath)
            m.add(base + "Stable", "yes" if c["stable"] else "no", vpath)
            m.add(base + "Adequate", "yes" if c["adequate"] else "no", vpath)
    u = v["unit"]
    for scene, qs in u["q"].items():
        for reading, q in zip(u["readings"], qs):
            m.math(f"v{prefix}Q{SCENE[scene]}{reading.title()}", sig(q, 3), vpath)
    m.add(f"v{prefix}UnitSelected", {"m": "N per metre of $h_t$", "mm": "N per millimetre of $h_t$",
                                     "rad": r"N per radian of $\alpha$", "deg": r"N per degree of $\alpha$"}.get(u["selected"], "none"),
          vpath)
    m.math(f"v{prefix}UnitTestQ", sig(u["test_q"], 3), vpath)
    m.add(f"v{prefix}UnitPassed", "passes" if u["passed"] else "fails", vpath)
    for c in v["curves"]:
        base = f"v{prefix}Curve{SCENE[c['scene']]}"
        m.add(base + "Points", str(c["points"]), vpath)
        m.add(base + "Within", str(c["within_two"]), vpath)
        m.math(base + "MedianZ", sig(c["median_abs_z"], 2), vpath)
        m.math(base + "RatioMin", sig(c["ratio_min"], 2), vpath)
        m.math(base + "RatioMax", sig(c["ratio_max"], 2), vpath)
        m.math(base + "JointChi", sig(c["joint_chi2"], 3), vpath)
        m.math(base + "JointP", sig(c["joint_p"], 2), vpath)
        m.math(base + "Toe", sig(c["force_below_delta"], 2), vpath)
        m.add(base + "JointWord", "consistent with" if c["jointly_consistent"] else "distinguishable from", vpath)
    # The profile's own fit, judged, and whether Eq. 7 then describes the averages within their
    # errors by the criteria's adequacy thresholds (the chosen candidate's verdict when it is the
    # profile's fit).
    adequate = []
    for scene, s in v["profile_fit"].items():
        if "judged" in s:
            m.math(f"v{prefix}Own{SCENE[scene]}Chi", sig(s["judged"]["chi2_per_dof"], 3), vpath)
            m.math(f"v{prefix}Own{SCENE[scene]}Runs", sig(s["judged"]["runs_z"], 2), vpath)
    adequate = [s["judged"]["adequate"] for s in v["profile_fit"].values() if "judged" in s]
    m.add(f"v{prefix}AdequateWord", "describes" if adequate and all(adequate) else "does not describe", vpath)
    # Seeds and the measured forces at a few deformations, from the averages' text columns.
    for scene in SCENE:
        path = os.path.join(d, "averages", f"normal-{scene}.dat")
        if not os.path.exists(path):
            continue
        rows = [l.split() for l in open(path) if l.strip() and not l.startswith("#")]
        for dn in ("0.3", "0.5"):
            for r in rows:
                if abs(float(r[0]) - float(dn)) < 1e-9:
                    m.math(f"v{prefix}{SCENE[scene]}F{'Three' if dn == '0.3' else 'Five'}", pm(float(r[1]), float(r[2])), path)
    fit = load(os.path.join(d, "fits", "soft-solid.json"))
    m.add(f"v{prefix}Seeds", str(fit["provenance"]["inputs"][0]["seeds"]), os.path.join(d, "fits", "soft-solid.json"))


def density_macros(m, path):
    j = load(path)
    m.math("vDensityMargin", sig(j["margin"], 2), path)
    m.math("vDensityDensest", f"{j['densest_solid_fraction']:.4f}", path)
    c = j["chosen"]
    m.math("vDensityBeta", f"{c['beta']:g}", path)
    m.math("vDensityTrials", sig(c["trials"], 2), path)
    for s in j["settings"]:
        if s["beta"] == c["beta"] and s["trials"] == c["trials"]:
            m.math("vDensityPhi", pm(*s["solid_fraction"]), path)
            m.math("vDensityGrains", f"{s['spheres'][0]:.0f}", path)
            m.math("vDensityExponent", pm(*s["exponent"]), path)
            m.math("vDensitySeconds", f"{s['seconds'][0]:.0f}", path)
    m.add("vDensitySettings", str(len(j["settings"])), path)
    m.add("vDensitySeeds", f"{j['seeds'][0]}--{j['seeds'][-1]}", path)


def thin(x):
    """An integer with thin spaces between thousands (LaTeX)."""
    return f"{x:,.0f}".replace(",", r"\,")


def curve_rows(curves):
    """A coarse report's curves.dat (coarse/report.cpp): each row's strain, phase, σzz resolved and
    its standard error, σzz soft and its standard error."""
    for line in open(curves):
        f = line.split()
        if line.startswith("#") or len(f) < 6:
            continue
        yield float(f[0]), int(f[1]), float(f[2]), float(f[3]), float(f[4]), float(f[5])


def coarse_macros(m, path):
    j = load(path)
    # The axial stress the soft-particle medium carries, as a fraction of the resolved one, over the
    # compression (phase 1) and unloading (phase -1) from a strain of 0.02 on (curves.dat beside).
    curves = os.path.join(os.path.dirname(path), "curves.dat")
    ratios = [soft / res for strain, phase, res, _, soft, _ in curve_rows(curves) if phase != 2 and strain >= 0.02 and res > 0]
    if ratios:
        m.math("vCoarseStressMin", sig(min(ratios), 2), curves)
        m.math("vCoarseStressMax", sig(max(ratios), 2), curves)
        m.add("vCoarseStressPoints", str(len(ratios)), curves)
    m.math("vCoarseSpeedup", pm(j["speedup"]["mean"], j["speedup"]["error"]), path)
    m.math("vCoarseResolvedSpheres", thin(j["spheres"]["resolved"]), path)
    m.math("vCoarseBodies", str(j["bodies"]), path)
    m.math("vCoarseMaxDn", sig(j["max_dn"], 2), path)  # the largest Δn its soft runs met
    m.add("vCoarseSeeds", ", ".join(str(s) for s in j["seeds"]), path)


LEVEL = {"3": "Three", "2": "Two", "1": "One", "0": "Zero"}
SETTING = {"reference": "Reference", "many-body": "ManyBody", "grains-reduced": "GrainsReduced", "on-resolved": "OnResolved",
           "resolved": "Resolved"}


def nested_macros(m, nested_dir, macro="vNested", levels=("1", "0"), committed_only=False):
    """Nested soft-particles' level reports (docs/nested.md, DATA/.../level-K/report/nested.json):
    per level and setting, its CPU time, each scene's onset δ and where it carries no force yet
    (Fn_unloaded_to), and its comparison with the setting it is compared against. The
    self-consistency test (make nested: levels 1 and 0, vNested...) must have both reports; the
    three-decade chain (make three-decades: vChain..., every level whose report is committed) has
    the levels it has run. A setting not run yet, or a comparison not made yet, has no macros."""
    for level in levels:
        word = LEVEL[level]
        path = os.path.join(nested_dir, f"level-{level}", "report", "nested.json")
        if committed_only and not os.path.exists(path):
            continue
        j = load(path)
        for name, s in j["settings"].items():
            if name not in SETTING:
                continue
            prefix = f"{macro}{word}{SETTING[name]}"
            m.math(prefix + "Cpu", thin(s["cpu_stages"]), path)
            for scene, law in s.get("scenes", {}).items():
                if law.get("Fn_unloaded_to") is not None:
                    m.math(f"{prefix}{SCENE[scene]}UnloadedTo", f"{law['Fn_unloaded_to']:g}", path)  # a grid value
                d = law.get("delta")
                if d and d.get("value") is not None:
                    m.math(f"{prefix}{SCENE[scene]}Delta", pm(d["value"], d.get("error")), path)
        for c in j.get("comparisons", []):
            if c["setting"] not in SETTING:
                continue
            name = f"{macro}{word}{SETTING[c['setting']]}"
            m.add(name + "Agree", str(c["agreeing"]), path)
            m.add(name + "Compared", str(c["compared"]), path)
            if c.get("closer_of"):
                m.add(name + "Nearer", str(c["closer"]), path)
                m.add(name + "NearerOf", str(c["closer_of"]), path)
            # nested / resolved over the compared points where the resolved mean is at least twice
            # its standard error (a ratio to a force indistinguishable from 0 says nothing)
            ratios = [p["ratio"]["value"] for p in c["points"]
                      if p["compared"] and p["ratio"]["value"] and p["against"]["value"] >= 2 * p["against"]["error"]]
            if ratios:
                m.math(name + "RatioMin", sig(min(ratios), 2), path)
                m.math(name + "RatioMax", sig(max(ratios), 2), path)


# The settings the three-decade medium runs on, level by level (docs/nested.md: the chain in the
# many-body form): level 3 grains only, level 2's many-body setting, levels 1 and 0 nested on it.
CHAIN_SETTINGS = {"3": "reference", "2": "many-body", "1": "reference", "0": "reference"}


def medium_macros(m, chain_dir):
    """The three-decade medium (make three-decades-medium, DATA/three-decades/medium/estimate/
    seed-S.json, committed): its soft runs' CPU time, the resolved model's estimated spheres and
    CPU time, the speed-up over the seeds (least and most), the four-decade plan's (the estimate's
    `plan`), and what measuring the laws it runs on cost (the chain's levels' reports: packings and
    stages of the settings it uses). Nothing before the estimates are committed."""
    paths = sorted(glob.glob(os.path.join(chain_dir, "medium", "estimate", "seed-*.json")))
    if not paths:
        return
    es = [load(p) for p in paths]
    src = os.path.join(chain_dir, "medium", "estimate", "seed-*.json")
    m.add("vMediumSeeds", ", ".join(str(e["seed"]) for e in es), src)
    soft = [e["soft_cpu"]["value"] for e in es]
    m.math("vMediumSoftCpuMin", sig(min(soft), 2), src)
    m.math("vMediumSoftCpuMax", sig(max(soft), 2), src)
    spheres = [e["resolved_spheres"]["value"] for e in es]
    m.math("vMediumResolvedSpheresMin", sig(min(spheres), 2), src)
    m.math("vMediumResolvedSpheresMax", sig(max(spheres), 2), src)
    days = [e["resolved_cpu_estimate"]["value"] / 86400 for e in es]
    m.math("vMediumResolvedCpuDaysMin", sig(min(days), 2), src)
    m.math("vMediumResolvedCpuDaysMax", sig(max(days), 2), src)
    # how far its soft-particles are pressed: the largest Δn its soft runs met, against the top of
    # the range level 0's laws were measured over (both scenes' normal law)
    m.math("vMediumMaxDnMin", sig(min(e["soft_max_dn"] for e in es), 2), src)
    m.math("vMediumMaxDnMax", sig(max(e["soft_max_dn"] for e in es), 2), src)
    # where its stress is a result (experiments/three-decades.yaml): the last loading strain before
    # a soft run's first contact beyond the laws' range, least and most over the seeds
    within = [e.get("soft_within_laws", {}).get("strain") for e in es]
    if all(w is not None and w >= 0 for w in within):
        m.math("vMediumWithinStrainMin", f"{min(within):.3f}", src)
        m.math("vMediumWithinStrainMax", f"{max(within):.3f}", src)
        sz = [e["soft_within_laws"]["sigma_zz"]["value"] for e in es]
        m.math("vMediumWithinSigmaMin", sig(min(sz), 2), src)
        m.math("vMediumWithinSigmaMax", sig(max(sz), 2), src)
    laws0 = os.path.join(chain_dir, "level-0", "report", "reference", "laws.json")
    top = min(sc["normal"]["delta_n_range"][1] for sc in load(laws0)["scenes"].values())
    m.math("vMediumLawsDnTop", f"{top:g}", laws0)
    up = [e["speed_up_estimate"]["value"] for e in es]
    m.math("vMediumSpeedUpMin", sig(min(up), 2), src)
    m.math("vMediumSpeedUpMax", sig(max(up), 2), src)
    plans = [e["plan"] for e in es if "plan" in e]
    if len(plans) == len(es):
        m.add("vMediumPlanLevels", str(plans[0]["levels_added"]), src)
        ps = [p["resolved_spheres"]["value"] for p in plans]
        m.math("vMediumPlanSpheresMin", sig(min(ps), 2), src)
        m.math("vMediumPlanSpheresMax", sig(max(ps), 2), src)
        pd = [p["resolved_cpu_estimate"]["value"] / 86400 / 365.25 for p in plans]
        m.math("vMediumPlanCpuYearsMin", sig(min(pd), 2), src)
        m.math("vMediumPlanCpuYearsMax", sig(max(pd), 2), src)
        pu = [p["speed_up_estimate"]["value"] for p in plans]
        m.math("vMediumPlanSpeedUpMin", sig(min(pu), 2), src)
        m.math("vMediumPlanSpeedUpMax", sig(max(pu), 2), src)
    per_level = []
    for level, setting in CHAIN_SETTINGS.items():
        path = os.path.join(chain_dir, f"level-{level}", "report", "nested.json")
        st = load(path)["settings"].get(setting)
        if st is None:
            fail(f"{path}: no setting {setting!r}, which the medium's laws come from")
        per_level.append(st["cpu_packings"] + st["cpu_stages"])
    reports = os.path.join(chain_dir, "level-*", "report", "nested.json")
    m.math("vMediumLawsCpuHours", sig(sum(per_level) / 3600, 2), reports)
    m.math("vMediumLevelCpuHoursMax", sig(max(per_level) / 3600, 2), reports)


def loading_ratio(curves, strain):
    """σzz soft / resolved of a coarse report's curves.dat at the last loading row at or below
    `strain`, with its error from the two means' standard errors (not paired), and that row's strain."""
    best = None
    for e, phase, res, res_se, soft, soft_se in curve_rows(curves):
        if phase == 1 and e <= strain + 1e-9 and res > 0:
            r = soft / res
            best = (r, r * math.hypot(soft_se / soft if soft > 0 else 0.0, res_se / res), e)
    if best is None:
        fail(f"{curves}: no loading row with a resolved stress at or below strain {strain}")
    return best


def nested_medium_macros(m, report, one_level):
    """Soft against resolved at Π = √10 (make nested-medium, experiments/nested-medium.yaml): the
    coarse report's reference setting (the chain's level-2 soft-particles in the many-body form) and
    its pairwise setting, their σzz soft / resolved at the end of loading, the agreement strain, the
    speed-up, where the soft runs stay within the laws; beside the one-level medium's ratio in the
    same form (many-body-v6's `many-body` setting, `one_level`: its coarse.json). Nothing before the
    report is committed."""
    table = os.path.join(report, "coarse.json")
    if not os.path.exists(table):
        return
    rows = {r["setting"]: r for r in load(table)["rows"]}
    ref = rows.get("reference")
    if ref is None:
        fail(f"{table}: no setting 'reference'")
    m.add("vNestedMediumSeeds", ", ".join(str(x) for x in ref["seeds"]), table)
    m.math("vNestedMediumRatio", sig(ref["sigma_soft_over_resolved"], 2), table)
    m.math("vNestedMediumAgreement", f"{ref['agreement_strain']:.3f}", table)
    if "pairwise" in rows:
        m.math("vNestedMediumPairwiseRatio", sig(rows["pairwise"]["sigma_soft_over_resolved"], 2), table)
    summary = os.path.join(report, "reference", "summary.json")
    j = load(summary)
    m.math("vNestedMediumSpeedup", pm(j["speedup"]["mean"], j["speedup"]["error"]), summary)
    m.math("vNestedMediumResolvedSpheres", thin(j["spheres"]["resolved"]), summary)
    m.math("vNestedMediumCpuResolved", sig(sum(j["cpu_seconds"]["resolved"]) / len(j["cpu_seconds"]["resolved"]), 2), summary)
    m.math("vNestedMediumMaxDn", sig(j["max_dn"], 2), summary)
    within = j.get("within_laws_strain")
    if within is not None:
        m.math("vNestedMediumWithinStrain", f"{within:.3f}", summary)
        # the stress is a result up to there (experiments/nested-medium.yaml): the ratio at that strain,
        # the pairwise setting's at its own, and the one-level medium's (within its laws throughout:
        # its soft runs met no contact beyond them) at the same strain
        curves = os.path.join(report, "reference", "curves.dat")
        r, err, _ = loading_ratio(curves, within)
        m.math("vNestedMediumWithinRatio", pm(r, err), curves)
        pair = os.path.join(report, "pairwise", "summary.json")
        if os.path.exists(pair) and load(pair).get("within_laws_strain") is not None:
            pw = load(pair)["within_laws_strain"]
            r, err, _ = loading_ratio(os.path.join(report, "pairwise", "curves.dat"), pw)
            m.math("vNestedMediumPairwiseWithinRatio", pm(r, err), pair)
            m.math("vNestedMediumPairwiseWithinStrain", f"{pw:.3f}", pair)
        one_dir = os.path.join(os.path.dirname(one_level), "many-body")
        if load(os.path.join(one_dir, "summary.json"))["beyond_range"] != 0:
            fail(f"{one_dir}/summary.json: the one-level medium's soft runs met contacts beyond their laws")
        r, err, _ = loading_ratio(os.path.join(one_dir, "curves.dat"), within)
        m.math("vOneLevelManyBodyWithinRatio", pm(r, err), os.path.join(one_dir, "curves.dat"))
    one = {r["setting"]: r for r in load(one_level)["rows"]}.get("many-body")
    if one is None:
        fail(f"{one_level}: no setting 'many-body'")
    m.math("vOneLevelManyBodyRatio", sig(one["sigma_soft_over_resolved"], 2), one_level)
    # Against the reference medium by medium (the coarse report's paired shift, q at e*): the
    # many-body law's effect (pairwise) and the nesting's share (resolved-content, criterion in
    # experiments/nested-medium.yaml: more, less or within 2 se).
    verdict = {1: "more than", -1: "less than", 0: "as much as"}
    for setting, name in (("pairwise", "Pairwise"), ("resolved-content", "ResolvedContent")):
        shift = rows.get(setting, {}).get("paired_against_reference")
        if not shift:
            continue
        m.math(f"vNestedMedium{name}Shift", pm(shift["q"], shift["q_se"]), table)
        m.math(f"vNestedMedium{name}ShiftStrain", f"{shift['strain']:.3f}", table)
        if setting == "resolved-content":  # the ratios beside it (pairwise's are the text's within-laws ratios)
            m.math(f"vNestedMedium{name}ShiftRatio", pm(shift["ratio"], shift["ratio_se"]), table)
            m.math(f"vNestedMedium{name}ShiftReferenceRatio", pm(shift["reference_ratio"], shift["reference_ratio_se"]), table)
        m.add(f"vNestedMedium{name}ShiftVerdict", verdict[shift["sign"]], table)


def radius_macros(m, path):
    j = load(path)
    m.math("vRadiusReference", sig(j["R0"], 2), path)
    # The exponent of Fn at fixed dn over the whole range of radii, and over the largest doubling
    # (neighbouring radii), per variant (self-similar: grains scale with the shell; fixed: the
    # same grains) and scene.
    variant = {"self_similar": "Scaled", "fixed": "Fixed"}
    for s in j["scaling"]:
        if s["quantity"] not in ("Fn", "Fn, neighbouring radii"):
            continue
        name = f"vRadius{variant[s['variant']]}{SCENE[s['scene']]}"
        if s["quantity"] == "Fn":
            m.math(name, pm(s["exponent"]["value"], s["exponent"]["error"]), path)
            m.math(name + "Span", sig(s["R_max"] / s["R_min"], 2), path)
        elif s["R_min"] == min(t["R_min"] for t in j["scaling"] if t["variant"] == s["variant"]):
            m.math(name + "Small", pm(s["exponent"]["value"], s["exponent"]["error"]), path)
    for mixed in j.get("mixed", []):
        rules = {r["rule"].split(",")[0]: r["deviation"] for r in mixed["rules"]}
        dev = rules.get("reduced radius")
        if dev:
            ratio = [x / y for x, y in zip(mixed["measured"], mixed["predicted_reduced_radius"]) if y > 0]
            m.math("vRadiusMixedMin", sig(min(ratio), 2), path)
            m.math("vRadiusMixedMax", sig(max(ratio), 2), path)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--out", required=True)
    p.add_argument("--profile", required=True)
    p.add_argument("--select")
    p.add_argument("--density")
    p.add_argument("--radius")
    p.add_argument("--coarse")
    p.add_argument("--nested")
    p.add_argument("--chain")
    p.add_argument("--nested-medium", help="the nested medium's report folder (data/nested-medium/report)")
    p.add_argument("--one-level", help="the one-level medium's report in the same form (data/many-body-v6/report/coarse.json)")
    a = p.parse_args()
    m = Macros()
    profile_macros(m, a.profile, "")
    if a.select:
        profile_macros(m, a.select, "Sel")
    if a.density:
        density_macros(m, a.density)
    if a.radius:
        radius_macros(m, a.radius)
    if a.coarse:
        coarse_macros(m, a.coarse)
    if a.nested:
        nested_macros(m, a.nested)
    if a.chain:
        nested_macros(m, a.chain, "vChain", ("3", "2", "1", "0"), committed_only=True)
        medium_macros(m, a.chain)
    if a.nested_medium:
        nested_medium_macros(m, a.nested_medium, a.one_level)
    text = "% Generated by paper/variables.py from the result files named on each line; do not edit.\n" + "\n".join(m.lines) + "\n"
    # Written only when it changes: make runs this on every report build (the studies' committed
    # reports are read, not made, workflow/paper.mk), and the PDF is rebuilt only for new numbers.
    if os.path.exists(a.out) and open(a.out).read() == text:
        return
    tmp = a.out + ".tmp"
    os.makedirs(os.path.dirname(os.path.abspath(a.out)), exist_ok=True)
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, a.out)


if __name__ == "__main__":
    main()
