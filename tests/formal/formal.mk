# tests/formal/formal.mk — formal checks of the RTL (tests/formal/*.sby, yowasp-sby with Yices 2 from the venv):
#   make formal          every task of every check must pass (a table of results and seconds)
#   make formal-broken   the deliberately broken copies of tests/formal/<check>.broken files must fail
#   CHECK=<name>          only tests/formal/<name>.sby (both targets)
# Included by the top-level Makefile; the checks run from the repository root, into $(BUILD)/formal.
.PHONY: formal formal-broken
formal formal-broken: setup
	@CHECK=$(CHECK) BUILD=$(BUILD) VENV_BIN=$(abspath .venv/bin) bash tests/formal/run.sh $(if $(filter formal,$@),prove,broken)
