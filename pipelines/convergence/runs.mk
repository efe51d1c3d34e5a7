# The runs of a convergence study, shared by pipelines/convergence (the paper's load) and
# pipelines/convergence-wellposed (a load every mesh resolves). The including Makefile sets
# PROBLEM (problem.json), RULE (xfem-assemble integration options), REF (a directory with
# the reference's enriched.vtu and u.mtx) and PROBES (a CSV of points for xfem-probe).
# Run directories, each out/<family>-<mesh>/:
#   xfem-SIZE   X-FEM on an unstructured CGAL mesh of target edge length SIZE, not cut-aligned;
#   xgrid-NXxNYxNZ   X-FEM on a structured grid with NZ odd (z = 0.1 inside a cell layer);
#   cg-NXxNYxNZ  CG-FEM on a cut-aligned grid (NZ, NX even), the cut modelled by doubled nodes.
# Each ends with rms.json (against REF), solve.json, classify.json and probe.csv (PROBES sampled).

out/cut.vtp:
	mkdir -p $(@D)
	$(BIN)/xfem-mesh $(QUIET) cut-rect --beam-cut -o $@

# X-FEM: an unstructured mesh (xfem-*) or a structured grid (xgrid-*), classified against the cut.
out/xfem-%/mesh.vtu:
	mkdir -p $(@D)
	$(BIN)/xfem-mesh $(QUIET) unstructured-box --hi 0.03 0.06 0.2 --size $* -o $@
out/xgrid-%/mesh.vtu:
	mkdir -p $(@D)
	$(BIN)/xfem-mesh $(QUIET) box --cells $(subst x, ,$*) --hi 0.03 0.06 0.2 -o $@
out/x%/classified.vtu: out/x%/mesh.vtu out/cut.vtp
	$(BIN)/xfem-classify $(QUIET) $< --cut out/cut.vtp --summary $(@D)/classify.json -o $@
out/x%/system/system.json: out/x%/enriched.vtu out/cut.vtp $(PROBLEM)
	$(BIN)/xfem-assemble $(QUIET) $< --cut out/cut.vtp --problem $(PROBLEM) $(RULE) -o $(@D)
out/x%/rms.json: out/x%/u.mtx $(REF)/enriched.vtu $(REF)/u.mtx
	$(BIN)/xfem-rmserror $(QUIET) $(@D)/enriched.vtu --cut out/cut.vtp --solution $< \
	  --reference $(REF)/enriched.vtu --reference-solution $(REF)/u.mtx -o $@ > /dev/null
out/x%/probe.csv: out/x%/u.mtx $(PROBES)
	$(BIN)/xfem-probe $(QUIET) $(@D)/enriched.vtu --cut out/cut.vtp --solution $< --points $(PROBES) -o $@

# CG-FEM: cut-aligned grid with doubled nodes, no enrichment.
out/cg-%/mesh.vtu:
	mkdir -p $(@D)
	$(BIN)/xfem-mesh $(QUIET) box --cells $(subst x, ,$*) --hi 0.03 0.06 0.2 --beam-cut -o $@
out/cg-%/classified.vtu: out/cg-%/mesh.vtu
	$(BIN)/xfem-classify $(QUIET) $< --summary $(@D)/classify.json -o $@
out/cg-%/system/system.json: out/cg-%/enriched.vtu $(PROBLEM)
	$(BIN)/xfem-assemble $(QUIET) $< --problem $(PROBLEM) -o $(@D)
out/cg-%/rms.json: out/cg-%/u.mtx out/cg-%/classified.vtu $(REF)/enriched.vtu $(REF)/u.mtx
	$(BIN)/xfem-rmserror $(QUIET) $(@D)/classified.vtu --solution $< \
	  --reference $(REF)/enriched.vtu --reference-solution $(REF)/u.mtx -o $@ > /dev/null
out/cg-%/probe.csv: out/cg-%/u.mtx out/cg-%/classified.vtu $(PROBES)
	$(BIN)/xfem-probe $(QUIET) $(@D)/classified.vtu --solution $< --points $(PROBES) -o $@

# Shared by every family.
out/%/enriched.vtu: out/%/classified.vtu
	$(BIN)/xfem-enrich $(QUIET) $< -o $@
out/%/u.mtx: out/%/system/system.json
	$(BIN)/xfem-solve $(QUIET) $(<D) -o $@ --report $(@D)/solve.json

.SECONDARY:
