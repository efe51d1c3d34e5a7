# Shared by every pipeline: where the tools are, how chatty they are, and make's safety nets.
# BIN: the built tools (Makefile.examples passes its own); QUIET: -q for quiet runs, empty to see progress.
PIPELINES_DIR := $(dir $(lastword $(MAKEFILE_LIST)))
BIN ?= $(abspath $(PIPELINES_DIR)/../build/tools)
QUIET ?= -q
# Headless PNG rendering needs an X server: xvfb-run provides one when there is no display.
XVFB ?= $(if $(DISPLAY),,xvfb-run -a)
# A failed command leaves no target behind, so the next make reruns it.
.DELETE_ON_ERROR:

# The chain of tools every pipeline runs, written once:
#   mesh + cuts -> xfem-classify -> xfem-enrich -> xfem-assemble -> xfem-solve -> xfem-visualize, xfem-front
# A pipeline writes the rules of its own inputs (the mesh and the cuts: xfem-mesh, gmsh) and `all`,
# then states each run in a line (pipelines/organ/Makefile is the smallest example):
#   out/organ.vtu: | out                  (and out/cut.vtp, out: their rules)
#   	$(BIN)/xfem-mesh $(QUIET) organ --size $(SIZE) -o $@
#   $(eval $(call xfem_chain,out/,out/organ.vtu,out/cut.vtp,problem.json,$(RULE),reactions report))
#   $(eval $(call xfem_visualize,out/,out/deformed.vtu out/wound.vtp out/organ.png,--title "$(TITLE)"))
# The files of a run share a prefix P: "out/" names out/classified.vtu,
# out/enriched.vtu, out/system/, out/u.mtx; "out/fine/" a second run in out/fine/; "out/box-" names
# out/box-classified.vtu, ..., out/box-system/, out/box-u.mtx.
#
#   $(eval $(call xfem_chain,P,MESH,CUTS,PROBLEM,ASSEMBLE_OPTIONS,OUTPUTS))
#     the rules of run P from the mesh to the solution P u.mtx:
#     MESH              the mesh file (.vtu, .msh);
#     CUTS              the cut surfaces, one --cut each (none: CG-FEM, the cut is in the mesh);
#     PROBLEM           the problem file (docs/FORMATS.md);
#     ASSEMBLE_OPTIONS  xfem-assemble's other options, e.g. $(RULE);
#     OUTPUTS           the optional outputs wanted, any of: summary (P classified.json, xfem-classify's
#                       summary), reactions (P reactions.mtx, which xfem_visualize then shows),
#                       report (P solve.json).
#   $(eval $(call xfem_visualize,P,FILES,OPTIONS))
#     the picture of run P's deformed body (xfem-visualize): FILES are, in this order, the deformed
#     mesh, the cut faces, the PNG and optionally the ParaView script; OPTIONS the rest (--title,
#     --view, --scale, ...).
#   xfem-front's rule is the pipeline's own (its outputs, options and checks differ from one to the
#   next); it takes the run's files from the chain:
#     out/front.vtp out/front.csv &: $(call xfem_solution,P)
#     	$(call xfem_front,P) --radius 0.01 -o out/front.vtp --csv out/front.csv
#     xfem_solution is run P's enriched mesh, cuts, solution and problem file; xfem_front the
#     xfem-front command on them; xfem_cut_options the run's --cut options, for other tools.
#   XFEM_SOLVE is the solve command; a run solved otherwise sets it on its solution, e.g. PETSc
#   under MPI: out/fine/u.mtx: XFEM_SOLVE = $(MPIRUN) $(BIN)/xfem-solve $(QUIET) --backend petsc
# The call's arguments are expanded when it is made: set the variables they use (RULE, ...) before
# it. A comma ends an argument: keep text with commas (a title) in a variable, --title "$(TITLE)".
# Not on the chain: convergence/runs.mk (pattern rules over run directories named after their
# mesh, shared by both convergence studies), convergence-wellposed's reference levels and
# verification (pattern rules choosing options from the run's path), sweep (xfem-sweep does it all).
XFEM_SOLVE = $(BIN)/xfem-solve $(QUIET)
xfem_cut_options = $(addprefix --cut ,$(xfem_cuts.$(1)))
xfem_solution = $(1)enriched.vtu $(xfem_cuts.$(1)) $(1)u.mtx $(xfem_problem.$(1))
xfem_front = $(BIN)/xfem-front $(QUIET) $(1)enriched.vtu $(call xfem_cut_options,$(1)) --solution $(1)u.mtx \
  --problem $(xfem_problem.$(1))

# With reactions, u.mtx and reactions.mtx come from one xfem-solve: a grouped target (&:).
define xfem_chain
xfem_cuts.$(1) := $(3)
xfem_problem.$(1) := $(4)
xfem_reactions.$(1) := $(if $(filter reactions,$(6)),$(1)reactions.mtx)
$(1)classified.vtu: $(2) $(3)
	$$(BIN)/xfem-classify $$(QUIET) $$< $(addprefix --cut ,$(3)) -o $$@$(if $(filter summary,$(6)), --summary $(1)classified.json)
$(1)enriched.vtu: $(1)classified.vtu
	$$(BIN)/xfem-enrich $$(QUIET) $$< -o $$@
$(1)system/system.json: $(1)enriched.vtu $(3) $(4)
	$$(BIN)/xfem-assemble $$(QUIET) $$< $(addprefix --cut ,$(3)) --problem $(4) $(5) -o $(1)system
$(1)u.mtx $(if $(filter reactions,$(6)),$(1)reactions.mtx &:,:) $(1)system/system.json
	$$(XFEM_SOLVE) $(1)system -o $(1)u.mtx$(if $(filter reactions,$(6)), --reactions $(1)reactions.mtx)$(if $(filter report,$(6)), --report $(1)solve.json)
endef

define xfem_visualize
$(2) &: $(call xfem_solution,$(1)) $(xfem_reactions.$(1))
	$$(XVFB) $$(BIN)/xfem-visualize $$(QUIET) $$< $(call xfem_cut_options,$(1)) --solution $(1)u.mtx$(if $(xfem_reactions.$(1)), --reactions $(xfem_reactions.$(1))) \
	  --problem $(xfem_problem.$(1)) -o $(word 1,$(2)) --faces $(word 2,$(2)) --png $(word 3,$(2))$(if $(word 4,$(2)), --paraview $(word 4,$(2))) $(3)
endef
