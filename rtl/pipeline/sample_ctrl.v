// Sample controller of the shading pipeline (ours; the interpolation paper leaves the control open):
// SystemC twin modules/pipeline/sample_ctrl.h with the state of modules/pipeline/sample_fsm.h, state
// for state. A state machine on the FALLING edge of clk, so every strobe it drives falls at a falling
// edge, half a clock away from the rising edges where the geometry side changes the pins and the
// pixel controller acts. The next state is computed from the values before the edge (the SystemC FSM
// reads every input as it was before the edge) and every register and strobe takes it at the edge.
//   handshake   `ready` changes at falling edges only; a request (load_frame or start) present at a
//               falling edge with ready = 1 is taken there. load_frame: ctl15, ctl20, ctl22, ctl24
//               and ld_k fall a clock later (UA 60553, Fig. 3: the device's frame registers, k_d*I
//               and the ambient term); start: ld_job falls at the taking edge (the job registers)
//   check       a clock after the take: a job with m neither 0 nor m_min..m_max, len 0 or above 2^m,
//               an exact pixel (m = 0) marked quadratic, or (FD_M = M, 2..6) another m than M is
//               dropped: no sample, no pixel (the SystemC model reports it; a report is not hardware)
//   samples     one per two clocks: smp_sel picks it a clock ahead, ctl17 falls (RG2 latches N.H),
//               stays low a clock and rises while ld_iK falls (I(K) takes the colour); an exact
//               pixel's one sample goes to all four registers, a quadratic's three to I1..I3
//   hand-over   at the last sample's latch ld_d falls (the descriptor registers) and samples_ready
//               rises; seeing ld_e = 1 it falls, and no sample latches before the falling edge after
//               the interval registers latched (ld_e's fall)
// Parameters: FD_M = the SystemC constructor's fd_m (0: any m, the Horner unit or fd_eval_var; 2..6:
// the forward-difference evaluator built for that m); CLOCKED = its wait_valid (1: a clocked device,
// the squared-quadratic or square-and-multiply device, whose output 29 = dev_valid the sample waits
// for; 0: UA 60553's Fig. 1 device, output 29 = strobe 17, dev_valid not read); CARRY = its carry
// (1: a job whose first N.H / N.L codes are the last sample's, carry_hit, takes that colour from the
// last-sample registers, carry_sel = 1, no strobe 17; ld_last latches every sample's colour and codes).
// Every output changes at the falling edge where the SystemC FSM writes it, but smp_sel and
// carry_sel, which follow half a clock later (a hold fix, at smp_sel_q below): at every falling
// edge each output holds the SystemC output's value.
// No reset pin, as the SystemC module: the state starts idle, ready, ld_job and ctl17 high (their
// initialize(true)), every other output low (initial values).
`include "shading_formats.vh"
module sample_ctrl #(
    parameter FD_M = 0,
    parameter CLOCKED = 0,
    parameter CARRY = 0,
    parameter LEN_W = 16,  // sample_ctrl::len_bits (a SystemC constant of the module, no format)
    parameter M_W = 4,     // sample_ctrl::m_bits
    parameter SEL_W = 2    // sample_ctrl::sel_t: smp_sel picks one of four samples
) (
    input  wire             clk,
    input  wire             start, load_frame,
    input  wire [LEN_W-1:0] len,        // the job registers' outputs
    input  wire [M_W-1:0]   m,
    input  wire             deg2,
    input  wire             ld_e,
    input  wire             dev_valid,  // the device's output 29 (read only with CLOCKED = 1)
    input  wire             carry_hit,  // the job's first codes are the last sample's (read only with CARRY = 1)
    output reg              ready = 1'b1,
    output reg              ld_job = 1'b1,
    output reg              ld_d = 1'b0,
    output wire             ctl15,
    output reg              ctl17 = 1'b1,  // idle high: its first fall latches the first sample (Fig. 3)
    output wire             ctl20, ctl22, ctl24, ld_k,
    output reg  [SEL_W-1:0] smp_sel = {SEL_W{1'b0}},  // changes half a clock after the SystemC: smp_sel_q
    output wire             ld_i1, ld_i2, ld_i3, ld_i4,
    output reg              samples_ready = 1'b0,
    output reg              carry_sel = 1'b0,  // changes half a clock after the SystemC: smp_sel_q
    output reg              ld_last = 1'b0
);
    // sample_fsm::state and sample_fsm::bank, in their order.
    localparam [2:0] IDLE = 3'd0, FRAME = 3'd1, CHECK = 3'd2, LOW = 3'd3, VALID = 3'd4, HIGH = 3'd5,
                     COPY = 3'd6;
    // The sample registers' interval: free, full (samples_ready = 1), or being taken (ld_e seen at
    // this edge: the interval registers latch half a clock later, the sample registers not before).
    localparam [1:0] FREE = 2'd0, FULL = 2'd1, TAKING = 2'd2;
    localparam [M_W-1:0] M_MIN = `INTERP_M_MIN, M_MAX = `INTERP_M_MAX;
    localparam [31:0] FD_M_WORD = FD_M;
    localparam [M_W-1:0] M_FD = FD_M_WORD[M_W-1:0];

    // The FSM's state (sample_fsm's members; the statistics counters are not hardware).
    reg [2:0] state = IDLE;
    reg [1:0] bank = FREE;
    reg have_last = 1'b0;  // a sample was formed since the frame constants were loaded
    reg [2:0] sample = 3'd0, count = 3'd0;  // the sample being formed; the job's samples (1, 3, 4)
    reg frame_strobes = 1'b0;  // ctl15, ctl20, ctl22, ctl24 and ld_k: always written together
    reg [3:0] ld_i = 4'd0;     // ld_i4..ld_i1
    // smp_sel and carry_sel as the SystemC FSM writes them, at falling edges. The outputs take them
    // half a clock later, at the next rising edge (ours, a hold fix the zero-delay RTL needs): at the
    // edge where a sample latches, ld_iK and ld_last fall while smp_sel moves to the next sample (or 0
    // with a job taken) and carry_sel falls; the registers they strobe must take the colour and codes
    // of the sample just formed. The SystemC model gets that from its multiplexers' delay (the strobe
    // falls at the edge, the bus changes a mux delay later); in the RTL the strobed registers latch
    // after the edge's clocked updates have settled through the logic, so a select moved at that edge
    // would reach them. Every reader is at a falling edge at least a clock later (RG2 at ctl17's fall,
    // the next latch), and at every falling edge the outputs hold what the SystemC outputs hold.
    reg [SEL_W-1:0] smp_sel_q = {SEL_W{1'b0}};
    reg carry_sel_q = 1'b0;

    assign ctl15 = frame_strobes;
    assign ctl20 = frame_strobes;
    assign ctl22 = frame_strobes;
    assign ctl24 = frame_strobes;
    assign ld_k = frame_strobes;
    assign ld_i1 = ld_i[0];
    assign ld_i2 = ld_i[1];
    assign ld_i3 = ld_i[2];
    assign ld_i4 = ld_i[3];

    // The job's check (pipeline::job_problem, job_samples in sample_fsm.h): the job's samples, 0 for
    // a job dropped. The job registers latched a clock before the check reads them.
    wire [LEN_W:0] len_cap = {{LEN_W{1'b0}}, 1'b1} << m;  // 2^m (read only for m <= m_max)
    wire m_bad = m != 0 && (m < M_MIN || m > M_MAX);
    wire len_bad = len == 0 || {1'b0, len} > len_cap;
    wire exact_quad = m == 0 && deg2;
    wire fd_other_m = FD_M != 0 && m != 0 && m != M_FD;
    wire [2:0] job_count = (m_bad || len_bad || exact_quad || fd_other_m) ? 3'd0
                         : m == 0 ? 3'd1 : deg2 ? 3'd3 : 3'd4;

    // Next values: sample_fsm::falling() step for step. begin_sample, latch_sample and take_request
    // are flags set by the states and run after the case in the C++ order (begin or latch, then
    // take), so every read sees what the C++ sees at that point of the call.
    reg [2:0] state_n, sample_n, count_n;
    reg [1:0] bank_n;
    reg have_last_n, frame_n, ready_n, ld_job_n, ld_d_n, ctl17_n, samples_ready_n, carry_sel_n, ld_last_n;
    reg [3:0] ld_i_n;
    reg [SEL_W-1:0] smp_sel_n;
    reg begin_smp, latch_smp, take;

    always @(*) begin
        state_n = state;
        bank_n = bank;
        have_last_n = have_last;
        sample_n = sample;
        count_n = count;
        frame_n = frame_strobes;
        ready_n = ready;
        ld_job_n = ld_job;
        ld_d_n = ld_d;
        ctl17_n = ctl17;
        smp_sel_n = smp_sel_q;
        ld_i_n = ld_i;
        samples_ready_n = samples_ready;
        carry_sel_n = carry_sel_q;
        ld_last_n = ld_last;
        begin_smp = 1'b0;
        latch_smp = 1'b0;
        take = 1'b0;

        // The hand-over: the interval registers latched at ld_e's fall, half a clock ago.
        if (bank_n == TAKING) bank_n = FREE;
        if (bank_n == FULL && ld_e) begin
            bank_n = TAKING;
            samples_ready_n = 1'b0;
        end
        case (state)
            IDLE: take = 1'b1;
            FRAME: begin
                frame_n = 1'b0;  // RG1, RG3-5, k_d*I and ambient latch
                ready_n = 1'b1;
                state_n = IDLE;
            end
            CHECK: begin
                count_n = job_count;
                if (job_count == 3'd0) begin  // dropped: ready again, nothing formed
                    ready_n = 1'b1;
                    ld_job_n = 1'b1;
                    state_n = IDLE;
                end else begin
                    sample_n = 3'd0;
                    begin_smp = 1'b1;
                end
            end
            LOW: begin  // strobe 17 has been low a clock: the device's settling phase
                if (CLOCKED != 0) begin
                    ctl17_n = 1'b1;  // validate: output 29 follows once the device is done
                    state_n = VALID;
                end else if (bank_n == FREE) begin  // else the previous interval is still in I1..I4
                    ctl17_n = 1'b1;
                    latch_smp = 1'b1;
                end
            end
            VALID: if (bank_n == FREE && dev_valid) latch_smp = 1'b1;
            COPY: if (bank_n == FREE) begin  // the carried colour waits only for the sample registers
                carry_sel_n = 1'b0;
                latch_smp = 1'b1;
            end
            HIGH: begin_smp = 1'b1;
            default: ;
        endcase

        // begin_sample: strobe 17 falls (RG2 latches N.H of sample `sample`), or the carry.
        if (begin_smp) begin
            if (sample_n == 3'd0 && CARRY != 0 && have_last_n && carry_hit) begin
                carry_sel_n = 1'b1;  // the colour bus carries the last sample's colour
                state_n = COPY;
            end else begin
                ctl17_n = 1'b0;
                state_n = LOW;
            end
            if (count_n == 3'd1) ld_i_n = 4'b1111;  // an exact pixel: all four registers
            else ld_i_n[sample_n[1:0]] = 1'b1;
            if (CARRY != 0) ld_last_n = 1'b1;
            if (sample_n + 3'd1 == count_n) ld_d_n = 1'b1;
        end
        // latch_sample: I(K) takes ambient + diffuse + specular (or the carried colour), and so do
        // the last-sample registers.
        if (latch_smp) begin
            if (count_n == 3'd1) ld_i_n = 4'b0000;
            else ld_i_n[sample_n[1:0]] = 1'b0;
            if (CARRY != 0) ld_last_n = 1'b0;
            have_last_n = 1'b1;
            sample_n = sample_n + 3'd1;
            if (sample_n < count_n) begin
                smp_sel_n = sample_n[SEL_W-1:0];
                state_n = HIGH;
            end else begin
                ld_d_n = 1'b0;  // the descriptor registers latch this job's y, x0, len, m, deg2
                samples_ready_n = 1'b1;
                bank_n = FULL;
                state_n = IDLE;
                if (CLOCKED != 0) begin  // not announced ahead: the source learns it at the next rising edge
                    ready_n = 1'b1;
                    ld_job_n = 1'b1;
                end else begin
                    take = 1'b1;  // the next job may be taken at this same edge (ready is 1 already)
                end
            end
        end
        // take_request.
        if (take) begin
            if (load_frame) begin
                have_last_n = 1'b0;  // new frame constants: the last colour is not this frame's
                frame_n = 1'b1;
                ready_n = 1'b0;
                state_n = FRAME;
            end else if (start) begin
                ready_n = 1'b0;
                ld_job_n = 1'b0;  // the job registers latch the pins now
                smp_sel_n = {SEL_W{1'b0}};
                state_n = CHECK;
            end
        end
        // The last sample's latch is the edge where the next request can be taken (Fig. 1 device):
        // announce it one clock ahead, once it is sure to happen there (the sample registers free
        // by then).
        if (CLOCKED == 0 && (state_n == LOW || state_n == COPY) && sample_n + 3'd1 == count_n && bank_n != FULL &&
            !ready_n) begin
            ready_n = 1'b1;
            ld_job_n = 1'b1;
        end
    end

    always @(negedge clk) begin
        state <= state_n;
        bank <= bank_n;
        have_last <= have_last_n;
        sample <= sample_n;
        count <= count_n;
        frame_strobes <= frame_n;
        ready <= ready_n;
        ld_job <= ld_job_n;
        ld_d <= ld_d_n;
        ctl17 <= ctl17_n;
        smp_sel_q <= smp_sel_n;
        ld_i <= ld_i_n;
        samples_ready <= samples_ready_n;
        carry_sel_q <= carry_sel_n;
        ld_last <= ld_last_n;
    end

    always @(posedge clk) begin
        smp_sel <= smp_sel_q;
        carry_sel <= carry_sel_q;
    end
endmodule
