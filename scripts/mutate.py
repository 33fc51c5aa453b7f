#!/usr/bin/env python3
"""Mutation check: do the tests fail when a key line of the code is wrong?

Each mutant is one plausible bug (a sign flipped, a factor of 2, `>` for `>=`, a term dropped) put into
a key line of a constitutive model or integrator, the material-point driver, an SPH stage or the rest
criterion. The line is found by a text pattern that must occur exactly once in its file (not by line
number, so the list survives edits); a pattern not found, or found twice, makes the mutant "not
applicable" in the report rather than an error.

The working tree is never modified: the script copies the tracked and untracked (not ignored) files
into a temporary directory, configures a build there (-O1 without link-time optimisation, through
ccache, so that a rebuild per mutant takes minutes rather than tens of minutes), checks that the unmutated copy passes every test group used, then for each mutant: applies
it, rebuilds the test executables of its file, runs the Catch2 tests that cover the file (the mapping
FILE_TESTS below, by tag), reports killed (some test failed), survived (all passed), or stillborn (it
does not compile), and restores the file.

Not part of CI or ctest: run on demand (a rebuild per mutant takes minutes on a loaded 2-core
machine). docs/validation/mutation-testing.md records a run and what became of its survivors.

  scripts/mutate.py --list                    # the mutants and whether their patterns apply
  scripts/mutate.py [--only ID,ID] [--first N --count M] [--report FILE] [--jobs 2]
"""
from __future__ import annotations

import argparse
import dataclasses
import filecmp
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


@dataclasses.dataclass(frozen=True)
class Run:
    """One test executable to rebuild and the Catch2 test spec to run in it ("" for all of it).

    With `sources`, the executable is the run's own: those test sources (paths under tests/) linked with
    `libraries`, added to the copy's build (never to the repository's). A header of sph/ reaches every
    translation unit of test_sph through sph/solver.h, so the run builds only the few test sources that
    exercise the mutated file instead of all twenty; test_verification also depends on the whole
    soilsph executable (for its CLI tests), which its subset here does not."""

    target: str
    spec: str = ""
    sources: tuple[str, ...] = ()
    libraries: tuple[str, ...] = ()


@dataclasses.dataclass(frozen=True)
class Tests:
    """What covers a file: the executables to rebuild and, for each, the Catch2 test spec to run."""

    runs: tuple[Run, ...]

    @property
    def targets(self) -> list[str]:
        return sorted({r.target for r in self.runs})


SPH_LIBS = ("soilsph_sph", "soilsph_sph_output")


def sph_run(name: str, spec: str, *files: str) -> Run:
    return Run(f"mutation_{name}", spec, tuple(f"sph/{f}" for f in files), SPH_LIBS)


# The exact tests of a stage (the ghost mirrors, eq 11, 12, 23, 37, the artificial stress) call only the
# neighbour search and the momentum stage of the SPH library. Linked with those sources instead of the
# libraries, their executable rebuilds one to three translation units for a mutant of a stage, where
# one linked with the libraries rebuilds the seven that include the stages (solver.cpp among them),
# tens of minutes on a loaded machine. It runs first; the one with the libraries only for a mutant it
# lets through.
SPH_STAGE_SOURCES = ("../sph/neighbours/cell_list.cpp", "../sph/neighbours/neighbour_list.cpp",
                     "../sph/stages/momentum.cpp")


def sph_exact_run(name: str, spec: str, *files: str) -> Run:
    return Run(f"mutation_{name}", spec, tuple(f"sph/{f}" for f in files) + SPH_STAGE_SOURCES,
               ("soilsph_constitutive", "OpenMP::OpenMP_CXX"))


STAGE_EXACT = sph_exact_run("stages_exact", "[stages],[velocity-gradient],[sph][stress]", "test_stages.cpp",
                            "test_velocity_gradient.cpp")


# The material-point driver's tests without the CLI ones (test_point_cli.cpp runs the soilsph executable).
DRIVER_RUN = Run("mutation_driver", "", ("verification/test_point_driver.cpp", "verification/test_cvode_reference.cpp",
                                         "verification/test_strain_path_csv.cpp", "verification/test_programme.cpp"),
                 ("soilsph_verification",))
# In order of cost (the run stops at the first executable that fails): test_closed_form, minutes on a
# loaded machine, runs only for a mutant the quick ones let through.
CONSTITUTIVE = Tests((Run("test_constitutive"), Run("test_integrators_point"), Run("test_closed_form")))
DRIVER = Tests((DRIVER_RUN, Run("test_integrators_point"), Run("test_closed_form")))
SPH_STAGES = Tests((STAGE_EXACT,
                    sph_run("stages", "[stages],[boundaries],[leapfrog],[walls],[velocity-gradient]", "test_stages.cpp",
                            "test_velocity_gradient.cpp", "test_time_integration.cpp", "test_boundaries.cpp",
                            "test_walls.cpp", "test_ghost_mirror.cpp")))

# The one-step check of each material group's model (tests/sph/test_materials.cpp), by name: the
# [sph][materials] tag also holds runs to rest at 2 mm, minutes each in this build.
OWN_MODEL = "each group's particles are updated by their own material's model*"

# The tests covering each file (by Catch2 tag or name), chosen to run in a minute or two each. The
# sources listed for an SPH file are those holding the tests of the spec.
FILE_TESTS: dict[str, Tests] = {
    "sph/rest.h": Tests((sph_run("rest", "[rest]", "test_time_integration.cpp"),)),
    "sph/stages/boundaries.h": Tests((sph_exact_run("mirror", "[mirror]", "test_ghost_mirror.cpp"),
                                      sph_run("boundaries", "[boundaries],[walls]", "test_ghost_mirror.cpp",
                                              "test_boundaries.cpp", "test_walls.cpp"))),
    "sph/stages/momentum.h": SPH_STAGES,
    "sph/stages/artificial_stress.h": SPH_STAGES,
    "sph/stages/velocity_gradient.h": SPH_STAGES,
    "sph/stages/leapfrog.h": SPH_STAGES,
    "sph/stages/stress_update.h": Tests((STAGE_EXACT,
                                         sph_run("stress_update", f"[stages],[sph][stress],{OWN_MODEL}",
                                                 "test_stages.cpp", "test_materials.cpp"))),
    "sph/solver.cpp": Tests((sph_run("groups", f"{OWN_MODEL},the two-material column groups*", "test_materials.cpp"),)),
    "verification/driver/mixed_control.h": DRIVER,
    "verification/driver/mixed_control_algebra.h": DRIVER,
}


def tests_for(path: str) -> Tests:
    if path in FILE_TESTS:
        return FILE_TESTS[path]
    if path.startswith("constitutive/"):
        return CONSTITUTIVE
    raise KeyError(f"no tests mapped for {path}")


def own_targets_cmake(runs: list[Run]) -> str:
    """The CMake of the run's own test executables, appended to the copy's tests/CMakeLists.txt."""
    text = "\n# Test executables of scripts/mutate.py's run (the copy's build only).\n"
    for r in sorted({r for r in runs if r.sources}, key=lambda r: r.target):
        text += (f"add_executable({r.target} {' '.join(r.sources)})\n"
                 f"target_link_libraries({r.target} PRIVATE {' '.join(r.libraries)} soilsph_catch_main "
                 "soilsph_warnings)\n"
                 f"target_compile_definitions({r.target} PRIVATE SOILSPH_SOURCE_DIR=\"${{PROJECT_SOURCE_DIR}}\")\n")
    return text


@dataclasses.dataclass(frozen=True)
class Mutant:
    id: str
    path: str
    find: str
    replace: str
    why: str  # the bug in words


M = Mutant
MUTANTS: list[Mutant] = [
    # --- sph/rest.h
    M("rest-movers-ge", "sph/rest.h", "if (moving > criterion_.movers_allowed(particles))",
      "if (moving >= criterion_.movers_allowed(particles))", "the allowed movers count as moving"),
    M("rest-duration-gt", "sph/rest.h", "return t - since_ >= criterion_.duration;",
      "return t - since_ > criterion_.duration;", "exactly the duration is not yet rest"),
    M("rest-fraction-flip", "sph/rest.h", "std::floor((1.0 - fraction) *", "std::floor((fraction) *",
      "allowed movers from the resting fraction"),
    M("rest-no-moved-gate", "sph/rest.h", "    if (!moved_) return false;\n", "",
      "a mass that never moved is taken for rest"),
    # --- sph/stages/boundaries.h
    M("mirror-normal-half", "sph/stages/boundaries.h", "v[0][b] = v_x - 2.0 * dn * nx", "v[0][b] = v_x - 1.0 * dn * nx",
      "the normal velocity reflection halved (x)"),
    M("mirror-stick-sign", "sph/stages/boundaries.h", "v[1][b] = v_y - 2.0 * dn * ny - 2.0 * s * dt * ty;",
      "v[1][b] = v_y - 2.0 * dn * ny + 2.0 * s * dt * ty;", "the no-slip tangential mirror's sign (y)"),
    M("mirror-wall-velocity-dropped", "sph/stages/boundaries.h", "const double dvx = v_x - p.wall_vx[g],",
      "const double dvx = v_x,", "the wall's own velocity ignored (x)"),
    M("mirror-shear-not-reversed", "sph/stages/boundaries.h", "const double change = (2.0 * tau - s_nt) - s_nt;",
      "const double change = (2.0 * tau - s_nt) - 0.0 * s_nt;", "the free-slip shear mirror dropped"),
    M("mirror-stick-le", "sph/stages/boundaries.h", "double stick = std::abs(s_nt) < limit ? 1.0 : 0.0;",
      "double stick = std::abs(s_nt) <= limit ? 1.0 : 0.0;", "sticks at the limit itself"),
    M("mirror-friction-sign", "sph/stages/boundaries.h", "tau = std::copysign(limit, slip)",
      "tau = std::copysign(limit, -slip)", "kinetic friction along the slip"),
    M("mirror-limit-tension", "sph/stages/boundaries.h", "mu * std::max(-s_nn, 0.0)", "mu * std::abs(s_nn)",
      "a wall in tension holds shear"),
    M("mirror-body-force-sign", "sph/stages/boundaries.h", "-(body.x * nx + body.y * ny) * (sums",
      "(body.x * nx + body.y * ny) * (sums", "the ghosts' weight carried upwards"),
    M("mirror-density-unaveraged", "sph/stages/boundaries.h", "p.density[b] = sums.density / sum_w;",
      "p.density[b] = sums.density;", "the ghost density not normalised"),
    # --- sph/stages: momentum, artificial stress, velocity gradient, leapfrog, stress update
    M("momentum-viscosity-sign", "sph/stages/momentum.h", "const double txx = a.sxx_rho2 + b.sxx_rho2 - pi;",
      "const double txx = a.sxx_rho2 + b.sxx_rho2 + pi;", "the viscosity pulls approaching particles (xx)"),
    M("momentum-shear-dropped", "sph/stages/momentum.h", "const double txy = a.sxy_rho2 + b.sxy_rho2;",
      "const double txy = a.sxy_rho2;", "the neighbour's shear stress dropped"),
    M("momentum-viscosity-beta-sign", "sph/stages/momentum.h", "(beta_ * hv - alpha_c_ * d) / (d * d * (a.density + b.density)));\n    const double txx",
      "(beta_ * hv + alpha_c_ * d) / (d * d * (a.density + b.density)));\n    const double txx", "the linear viscosity term's sign"),
    M("artificial-stress-compression", "sph/stages/artificial_stress.h",
      "const double r1 = s1 > 0.0 ? scale * s1 : 0.0;", "const double r1 = s1 < 0.0 ? scale * s1 : 0.0;",
      "artificial stress on compression instead of tension"),
    M("artificial-stress-scale-sign", "sph/stages/artificial_stress.h",
      "s2 = centre - radius;\n  const double scale = -epsilon /",
      "s2 = centre - radius;\n  const double scale = epsilon /", "artificial stress pulls"),
    M("velocity-gradient-transposed", "sph/stages/velocity_gradient.h", "L.l[a][b] += volume * dv[a] * q.g[b];",
      "L.l[a][b] += volume * dv[b] * q.g[a];", "∂v_x/∂y taken as ∂v_y/∂x"),
    M("continuity-sign", "sph/stages/velocity_gradient.h", "rate -= p.mass[j] * dot(dv, q.g);",
      "rate += p.mass[j] * dot(dv, q.g);", "eq 11's sign"),
    M("leapfrog-full-kick", "sph/stages/leapfrog.h", "return 0.5 * (previous_dt + dt);",
      "return previous_dt + dt;", "the kick interval doubled"),
    M("stress-update-no-split", "sph/stages/stress_update.h", "s = model.update(s, strain / parts, spin / parts);",
      "s = model.update(s, strain / parts, spin);", "each split part rotated by the whole spin"),
    M("groups-first-model", "sph/solver.cpp", "const Material& m = materials[k];", "const Material& m = materials[0];",
      "every group run with the first material's model"),
    # --- constitutive: Drucker-Prager
    M("dp-alpha-root", "constitutive/models/drucker_prager.cpp",
      "const double root = std::sqrt(9.0 + 12.0 * tan_phi * tan_phi);",
      "const double root = std::sqrt(9.0 + 6.0 * tan_phi * tan_phi);", "eq 19's 12 tan²φ halved"),
    M("dp-kc-factor", "constitutive/models/drucker_prager.cpp", "k_c_ = 3.0 * params.cohesion / root;",
      "k_c_ = 6.0 * params.cohesion / root;", "k_c doubled"),
    M("dp-yield-sign", "constitutive/models/drucker_prager.cpp",
      "return std::sqrt(second_deviatoric_invariant(sigma)) + alpha_phi_ * sigma.trace() - k_c_;",
      "return std::sqrt(second_deviatoric_invariant(sigma)) - alpha_phi_ * sigma.trace() - k_c_;",
      "the pressure term of the yield function's sign"),
    M("dp-flow-uses-phi", "constitutive/models/drucker_prager.cpp",
      "return sqrt_j2_gradient(sigma) + alpha_psi_ * Mat3::Identity();",
      "return sqrt_j2_gradient(sigma) + alpha_phi_ * Mat3::Identity();", "associated flow whatever ψ"),
    M("dp-implicit-denominator", "constitutive/integrators/implicit_drucker_prager.cpp",
      "const double A = D.G + 9.0 * alpha * D.K * alpha_psi;", "const double A = D.G + 3.0 * alpha * D.K * alpha_psi;",
      "the return's denominator n_f:D:n_g"),
    M("dp-implicit-volumetric", "constitutive/integrators/implicit_drucker_prager.cpp",
      "const double I1_next = I1 - 9.0 * D.K * alpha_psi * d_lambda;",
      "const double I1_next = I1 + 9.0 * D.K * alpha_psi * d_lambda;", "plastic dilation contracts"),
    M("dp-implicit-elastic-ge", "constitutive/integrators/implicit_drucker_prager.cpp", "if (f_trial <= 0.0) {",
      "if (f_trial < 0.0) {", "the yield surface itself returns (equivalent?)"),
    # --- constitutive: Modified Cam-Clay
    M("mcc-M-factor", "constitutive/models/modified_cam_clay.cpp", "M_ = 6.0 * sin_phi / (3.0 - sin_phi);",
      "M_ = 6.0 * sin_phi / (3.0 + sin_phi);", "eq 26 for extension"),
    M("mcc-yield-q-factor", "constitutive/models/modified_cam_clay.cpp",
      "return M_ * M_ * p * (p - pc) + 3.0 * second_deviatoric_invariant(sigma);",
      "return M_ * M_ * p * (p - pc) + 1.5 * second_deviatoric_invariant(sigma);", "q² = 3 J2 halved"),
    M("mcc-gradient-pc", "constitutive/models/modified_cam_clay.cpp",
      "return -M_ * M_ * (2.0 * p - pc) / 3.0 * Mat3::Identity() + 3.0 * deviator(sigma);",
      "return -M_ * M_ * (p - pc) / 3.0 * Mat3::Identity() + 3.0 * deviator(sigma);", "∂f/∂p's 2p"),
    M("mcc-theta-kappa-sign", "constitutive/models/modified_cam_clay.cpp",
      "(params.compression_index - params.swelling_index)", "(params.compression_index + params.swelling_index)",
      "eq 27's λ − κ"),
    M("mcc-initial-pc", "constitutive/models/modified_cam_clay.cpp",
      "const double on_surface = p > 0.0 ? p + q * q / (M_ * M_ * p) : 0.0;",
      "const double on_surface = p > 0.0 ? p + q / (M_ * p) : 0.0;", "the initial surface through (p, q)"),
    # --- constitutive: Mohr-Coulomb
    M("mc-function-sign", "constitutive/models/mohr_coulomb.cpp",
      "return (s(0) - s(2)) + (s(0) + s(2)) * sin_phi - cohesion_term;",
      "return (s(0) - s(2)) - (s(0) + s(2)) * sin_phi - cohesion_term;", "the Mohr-Coulomb friction term's sign"),
    M("mc-cohesion-factor", "constitutive/models/mohr_coulomb.cpp",
      "cohesion_term_(2.0 * params.cohesion * std::cos(", "cohesion_term_(params.cohesion * std::cos(",
      "2c cos φ halved"),
    M("mc-flow-uses-phi", "constitutive/models/mohr_coulomb.cpp",
      "  return plane_gradient(sigma, sin_psi_);", "  return plane_gradient(sigma, sin_phi_);",
      "associated flow whatever ψ"),
    M("mc-gradient-minor", "constitutive/models/mohr_coulomb.cpp", "Vec3 a(1.0 + sin_angle, 0.0, -(1.0 - sin_angle));",
      "Vec3 a(1.0 + sin_angle, 0.0, -(1.0 + sin_angle));", "the minor principal stress's gradient"),
    # --- constitutive: elasticity, rotation, explicit and substep integrators
    M("elastic-bulk-factor", "constitutive/elasticity.cpp", "young_modulus / (3.0 * (1.0 - 2.0 * poisson_ratio))",
      "young_modulus / (3.0 * (1.0 - poisson_ratio))", "K = E/(3(1 − 2ν)) without the 2"),
    M("elastic-kappa-star", "constitutive/elasticity.cpp", "e.kappa_star_ = swelling_index / (1.0 + initial_void_ratio);",
      "e.kappa_star_ = swelling_index / initial_void_ratio;", "κ* = κ/(1 + e0) without the 1"),
    M("rotation-half-spin", "constitutive/rotation.h", "const Mat3 half = 0.5 * spin_increment;",
      "const Mat3 half = spin_increment;", "the Cayley rotation by twice the spin"),
    M("rotation-transpose", "constitutive/rotation.h", "rotated.stress = Q * state.stress * Q.transpose();",
      "rotated.stress = Q.transpose() * state.stress * Q;", "the stress rotated against the spin"),
    M("explicit-consistency-sign", "constitutive/integrators/explicit_rate.h",
      "const double numerator = model.yield(sigma, start.pc) + ddot(n_f, elastic_stress_increment);",
      "const double numerator = model.yield(sigma, start.pc) - ddot(n_f, elastic_stress_increment);",
      "the linearised consistency condition's sign"),
    M("explicit-no-hardening", "constitutive/integrators/explicit_rate.h",
      "std::max(elastic_part + model.hardening_modulus(sigma, start.pc), kMinDenominatorFraction * elastic_part);",
      "std::max(elastic_part, kMinDenominatorFraction * elastic_part);", "the hardening modulus dropped"),
    M("substep-average", "constitutive/integrators/substep.h",
      ".sigma = path.sigma + 0.5 * (r1.d_stress + r2.d_stress),",
      ".sigma = path.sigma + r2.d_stress,", "the modified-Euler average replaced by its second stage"),
    M("substep-error-lax", "constitutive/integrators/substep.h", "    if (step.error > tolerance) {\n",
      "    if (step.error > 10.0 * tolerance) {\n", "the error control ten times too lax"),
    # --- verification/driver
    M("driver-halving", "verification/driver/mixed_control.h", "for (int halving = 0;; ++halving, step *= 0.5) {",
      "for (int halving = 0;; ++halving, step *= 1.0) {", "the line search never shortens its step"),
    M("driver-tolerance", "verification/driver/mixed_control.h",
      "if (trial.norm <= options.tolerance * scale) return trial;",
      "if (trial.norm <= 1e3 * options.tolerance * scale) return trial;", "the equilibrium tolerance 1000× laxer"),
    M("driver-undrained-sign", "verification/driver/mixed_control_algebra.h",
      "A(part.n_free, a) = scale * voigt_identity(part.free[a]);",
      "A(part.n_free, a) = -scale * voigt_identity(part.free[a]);", "the undrained constraint's sign"),
    M("driver-fixed-coupling", "verification/driver/mixed_control_algebra.h",
      "for (int c = 0; c < part.n_fixed; ++c) rhs(a) -= C(part.free[a], part.fixed[c]) * x(part.fixed[c]);",
      "for (int c = 0; c < part.n_fixed; ++c) rhs(a) += C(part.free[a], part.fixed[c]) * x(part.fixed[c]);",
      "the imposed strains' coupling to the free ones"),
]


def applicable(tree: Path, m: Mutant) -> bool:
    path = tree / m.path
    return path.exists() and path.read_text().count(m.find) == 1


# A mutant can make a test print without end (a failed check in a loop): each command's output goes to
# a file of its own limited to this size, and only its tail reaches the log.
OUTPUT_LIMIT_BYTES = 64 << 20
LOG_TAIL_BYTES = 64 << 10
TIMED_OUT = -1000  # run()'s status for a command past its time limit (a signal gives -N)


def limit_output_size() -> None:
    resource.setrlimit(resource.RLIMIT_FSIZE, (OUTPUT_LIMIT_BYTES, OUTPUT_LIMIT_BYTES))


def run(cmd: list[str], cwd: Path, timeout: float, log) -> tuple[int, float]:
    start = time.monotonic()
    log.write(f"$ {' '.join(cmd)}\n")
    log.flush()
    with tempfile.TemporaryFile() as output:
        try:
            rc = subprocess.run(cmd, cwd=cwd, stdout=output, stderr=subprocess.STDOUT, timeout=timeout,
                                preexec_fn=limit_output_size).returncode
        except subprocess.TimeoutExpired:
            rc = TIMED_OUT
        size = output.seek(0, os.SEEK_END)
        output.seek(max(0, size - LOG_TAIL_BYTES))
        if size > LOG_TAIL_BYTES:
            log.write(f"[... {size - LOG_TAIL_BYTES} bytes of output cut ...]\n")
        log.write(output.read().decode(errors="replace"))
    log.flush()
    return rc, time.monotonic() - start


def copy_tree(dest: Path) -> None:
    """Brings the copy up to the working tree: only files whose bytes differ are written, so a copy
    kept from an earlier run (--work) rebuilds only what changed since."""
    files = subprocess.run(["git", "ls-files", "-co", "--exclude-standard", "-z"], cwd=ROOT, check=True,
                           capture_output=True).stdout.decode().split("\0")
    for f in filter(None, files):
        src = ROOT / f
        if not src.is_file() or f.startswith("build"):
            continue
        (dest / f).parent.mkdir(parents=True, exist_ok=True)
        if not (dest / f).exists() or not filecmp.cmp(src, dest / f, shallow=False):
            shutil.copy2(src, dest / f)
            os.utime(dest / f)  # newer than the objects built from the old text


def add_own_targets(tree: Path, runs: list[Run]) -> None:
    """Appends the run's own test executables to the copy's tests/CMakeLists.txt (once)."""
    cmake = tree / "tests" / "CMakeLists.txt"
    original = (ROOT / "tests" / "CMakeLists.txt").read_text()
    wanted = original + own_targets_cmake(runs)
    if cmake.read_text() != wanted:
        cmake.write_text(wanted)


def test_commands(build: Path, tests: Tests) -> list[list[str]]:
    return [[str(build / "tests" / r.target)] + ([r.spec] if r.spec else []) for r in tests.runs]


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--list", action="store_true", help="list the mutants and whether they apply, then exit")
    ap.add_argument("--only", help="comma-separated mutant ids, run in the order given")
    ap.add_argument("--first", type=int, default=0)
    ap.add_argument("--count", type=int, default=len(MUTANTS))
    ap.add_argument("--jobs", type=int, default=2, help="build jobs")
    ap.add_argument("--test-timeout", type=float, default=900.0, help="seconds per test command")
    ap.add_argument("--work", help="work directory (default: a new temporary one, removed at the end)")
    ap.add_argument("--keep", action="store_true", help="keep the work directory")
    ap.add_argument("--report", default="mutation-report.md", help="the report (Markdown), written as it goes")
    args = ap.parse_args()

    chosen = MUTANTS[args.first:args.first + args.count]
    if args.only:
        ids = args.only.split(",")
        unknown = set(ids) - {m.id for m in MUTANTS}
        if unknown:
            sys.exit(f"error: --only: unknown mutant(s) {', '.join(sorted(unknown))}")
        by_id = {m.id: m for m in MUTANTS}
        chosen = [by_id[i] for i in ids]  # in the order given
    ids = [m.id for m in MUTANTS]
    if len(ids) != len(set(ids)):
        sys.exit("error: duplicate mutant ids")

    if args.list:
        for m in chosen:
            print(f"{m.id:32} {m.path:48} {'applies' if applicable(ROOT, m) else 'NOT APPLICABLE'}  {m.why}")
        print(f"{len(chosen)} mutants, {sum(applicable(ROOT, m) for m in chosen)} applicable")
        return 0

    work = Path(args.work) if args.work else Path(tempfile.mkdtemp(prefix="soilsph-mutate-"))
    work.mkdir(parents=True, exist_ok=True)
    tree, log_path = work / "src", work / "mutate.log"
    build = tree / "build"
    report = Path(args.report).resolve()
    print(f"work directory {work}; log {log_path}; report {report}", flush=True)
    with open(log_path, "a") as log:
        tree.mkdir(parents=True, exist_ok=True)
        copy_tree(tree)
        add_own_targets(tree, [r for m in MUTANTS for r in tests_for(m.path).runs])
        # Built for speed, not for timing: -O1 without debug information or link-time optimisation
        # (a rebuild per mutant is the cost of the run; an LTO link of each test executable takes
        # minutes, and -O0 makes the tests that step a solver many times slower than they save in
        # compilation). The unmutated copy must pass every test used, so the flags cannot change what
        # the tests see unnoticed.
        env_cmake = ["cmake", "-S", str(tree), "-B", str(build), "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
                     "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -DNDEBUG", "-DCMAKE_CXX_COMPILER_LAUNCHER=ccache",
                     "-DSOILSPH_BUILD_BENCHMARKS=OFF", "-DSOILSPH_LTO=OFF"]
        if run(env_cmake, tree, 1800, log)[0] != 0:
            sys.exit(f"error: configuring the copy failed (see {log_path})")
        applicable_mutants = [m for m in chosen if applicable(tree, m)]
        targets = sorted({t for m in applicable_mutants for t in tests_for(m.path).targets})
        rc, seconds = run(["cmake", "--build", str(build), f"-j{args.jobs}", "--target", *targets], tree, 7200, log)
        if rc != 0:
            sys.exit(f"error: the unmutated copy does not build (see {log_path})")
        print(f"unmutated build: {seconds:.0f} s", flush=True)
        # The unmutated copy must pass every test command used: a failure there would "kill" every mutant.
        commands = sorted({tuple(c) for m in applicable_mutants for c in test_commands(build, tests_for(m.path))})
        for cmd in commands:
            rc, seconds = run(list(cmd), build, args.test_timeout, log)
            print(f"unmutated: {' '.join(Path(c).name if i == 0 else c for i, c in enumerate(cmd))}: "
                  f"{'pass' if rc == 0 else 'FAIL'} in {seconds:.0f} s", flush=True)
            if rc != 0:
                sys.exit(f"error: the unmutated copy fails {' '.join(cmd)} (see {log_path})")

        rows = []
        started = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
        commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT, capture_output=True,
                                text=True).stdout.strip()

        def write_report() -> None:
            counts = {}
            for r in rows:
                counts[r[2]] = counts.get(r[2], 0) + 1
            with open(report, "w") as out:
                out.write(f"# Mutation run of {started} (commit {commit} plus the working tree)\n\n")
                out.write(", ".join(f"{v} {k}" for k, v in sorted(counts.items())) + f" of {len(rows)} run\n\n")
                out.write("| mutant | file | outcome | by | build s | test s | the bug |\n|---|---|---|---|---|---|---|\n")
                for r in rows:
                    out.write("| " + " | ".join(str(x) for x in r) + " |\n")

        for m in chosen:
            if not applicable(tree, m):
                rows.append((m.id, m.path, "not applicable", "", "", "", m.why))
                write_report()
                print(f"{m.id}: not applicable", flush=True)
                continue
            path = tree / m.path
            original = path.read_text()
            stat = path.stat()
            path.write_text(original.replace(m.find, m.replace))
            tests = tests_for(m.path)
            log.write(f"\n===== mutant {m.id}: {m.path}: {m.why}\n")
            try:
                # One executable at a time, in the order listed (the quickest and closest first): a
                # mutant killed by the first is not rebuilt into the others.
                outcome, killer, build_s, test_s = "survived", "", 0.0, 0.0
                for r, cmd in zip(tests.runs, test_commands(build, tests)):
                    rc, seconds = run(["cmake", "--build", str(build), f"-j{args.jobs}", "--target", r.target], tree,
                                      7200, log)
                    build_s += seconds
                    if rc != 0:
                        outcome, killer = "stillborn (does not compile)", r.target
                        break
                    rc, seconds = run(cmd, build, args.test_timeout, log)
                    test_s += seconds
                    if rc != 0:
                        outcome = ("killed (timeout)" if rc == TIMED_OUT
                                   else "killed" if rc > 0 else f"killed (signal {-rc})")
                        killer = r.target
                        break
            finally:
                path.write_text(original)
                os.utime(path, ns=(stat.st_atime_ns, time.time_ns()))  # newer: its dependants rebuild
            rows.append((m.id, m.path, outcome, killer, f"{build_s:.0f}", f"{test_s:.0f}", m.why))
            write_report()
            print(f"{m.id}: {outcome} (build {build_s:.0f} s, tests {test_s:.0f} s)", flush=True)
    if not args.work and not args.keep:
        shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
