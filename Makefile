# rosbook-one: the README's two commands are `make demo` and `make test`.
.PHONY: setup build demo test test-fast bench clean

setup:
	@./scripts/setup.sh

build:
	@./scripts/build.sh

demo: setup
	@./scripts/demo.sh $(ARGS)

test: setup
	@./scripts/test.sh $(ARGS)

# The quick tier for the edit-test loop (unit tests, gtests, a few short integration tests).
test-fast: setup
	@ROSBOOK_TIER=fast ./scripts/test.sh $(ARGS)

bench: setup
	@./scripts/bench.sh

clean:
	rm -rf catkin_ws/build catkin_ws/devel catkin_ws/install
