//! drcc-testbench: scenarios and their runner.
