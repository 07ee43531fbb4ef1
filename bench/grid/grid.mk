# bench/grid/grid.mk - `make bench-grid`: chapter 11's fast grid (its lab) against chapter 04's
# linear scan and Intel Embree 3 (included by the Makefile; `make bench` may call it).
#
# Gets its own Debian packages (tools/deps.sh bench-grid: libembree-dev, and
# glmark2-data for the Stanford bunny), builds bench/grid/grid_vs_embree.c with
# the solutions' stage files of chapters 01-11, and runs bench/grid/run.sh.
# Nothing here is built by `make` or `make test`.

BENCH_GRID := $(BUILD)/bench/grid/grid_vs_embree

.PHONY: bench-grid
bench-grid:
	@tools/deps.sh "$(CC)" bench-grid
	@$(MAKE) --no-print-directory STUDENT=0 SANITIZE=0 $(BENCH_GRID)
	@bench/grid/run.sh $(BENCH_GRID)

# The reference (solution) stage objects of chapters 01-11, as the renderers link them, and the fast grid.
BENCH_GRID_OBJS := $(call objs,bench/grid/grid_vs_embree.c bench/grid/workload.c) $(foreach c,$(call upto,11_grid),$(call stage_objs,$c,0)) \
                   $(call lab_objs,11_grid) \
                   $(call objs,$(COMMON_SRC))

$(BENCH_GRID): $(BENCH_GRID_OBJS)
	@mkdir -p $(@D)
	$(QLINK)$(call link,$^) -lembree3 -o $@
