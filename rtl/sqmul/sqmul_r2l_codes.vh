// Select codes of the right-to-left square-and-multiply design's two register multiplexers, MX_X
// and MX_P (sqmul_r2l_ctrl.v drives them, sqmul_r2l_stage.v wires the inputs at them). No SystemC
// model shares them: this is their one definition.
`ifndef SQMUL_R2L_CODES_VH
`define SQMUL_R2L_CODES_VH
`define SQMUL_R2L_MX_INPUTS 3
`define SQMUL_R2L_SEL_W 2
`define SQMUL_R2L_HOLD 0     // RG_X, RG_P keep their words
`define SQMUL_R2L_LOAD 1     // RG_X <- cos (clamped to 1.0 in saturate mode), RG_P <- 1.0
`define SQMUL_R2L_PRODUCT 2  // RG_X <- MUL_X = X^2, RG_P <- MUL_P = P x X
`endif
