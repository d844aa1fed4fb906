// Select codes of the square-and-multiply baseline's multiplexers (sqmul_ctrl.v drives them,
// sqmul_stage.v wires the inputs at them). No SystemC model shares them: this is their one
// definition.
`ifndef SQMUL_CODES_VH
`define SQMUL_CODES_VH
`define SQMUL_MX_P_INPUTS 3
`define SQMUL_MX_P_SEL_W 2
`define SQMUL_MX_P_HOLD 0     // RG_P keeps its word
`define SQMUL_MX_P_LOAD 1     // RG_P <- cos (Q1.18, clamped to 1.0 in saturate mode)
`define SQMUL_MX_P_PRODUCT 2  // RG_P <- MUL_P
`define SQMUL_MX_B_INPUTS 2
`define SQMUL_MX_B_P 0        // MUL_P = P x P (a square)
`define SQMUL_MX_B_COS 1      // MUL_P = P x cos (a multiplication)
`endif
