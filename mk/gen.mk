# mk/gen.mk — the build table made into make: mk/gen_builds.py writes $(GEN_DIR)/builds.mk (the
# simulators' ids and lists, read here), gpusim.mk (the GPU simulators' rules, read by the
# Makefile), socsim.mk (the SoC simulators', read by cosim/soc/socsim.mk) and firmware.mk (the
# firmware's object variants and programs, read by firmware/firmware.mk) from mk/builds.toml,
# tests/suites.toml, the scene table, the contract, the memory map and the manifests.
#
# Generated while the makefiles are read, before any rule runs, and only when an input is newer
# than the last output (builds.mk is the stamp): make's own remaking of included files would read
# everything twice. On a machine without Python yet (a fresh Debian before `make setup`), nothing
# is generated: `make run` and `make test` install it first and read the makefiles again in their
# second make; any other goal says what to do.
GEN_DIR    := $(BUILD)/gen
GEN_INPUTS := mk/builds.toml tests/suites.toml mk/gen_builds.py mk/manifest.py \
              firmware/scenes/scene_list.h firmware/scenes/model/model.h contract/gpu_contract.toml \
              contract/soc_map.toml $(wildcard firmware/scenes/*.manifest.toml)
GEN_STALE  := $(shell test -f $(GEN_DIR)/builds.mk && find $(GEN_INPUTS) -newer $(GEN_DIR)/builds.mk | head -n 1 \
                      || echo missing)
ifneq ($(shell command -v $(PYTHON) 2>/dev/null),)
ifneq ($(GEN_STALE),)
GEN_ERROR := $(shell $(PYTHON) mk/gen_builds.py --out $(GEN_DIR) 2>&1 >/dev/null && touch $(GEN_DIR)/builds.mk)
ifneq ($(GEN_ERROR),)
$(error $(GEN_ERROR))
endif
endif
GEN_READ := 1
else ifeq ($(filter-out setup run test fresh-check clean,$(or $(MAKECMDGOALS),all)),)
GEN_READ :=
else
$(error $(PYTHON) not found: `make setup` installs what the build needs)
endif
ifneq ($(GEN_READ),)
include $(GEN_DIR)/builds.mk
endif
