// skylux_core: the whole Skylux fabric core, exported from rust-hdl by
// `cargo run -p skylux-bitstream -- verilog`. Generated: do not edit.


module skylux_core(clk,avs_address,avs_read,avs_write,avs_writedata,avs_byteenable,avs_readdata,irq,dma_address,dma_burstcount,dma_write,dma_writedata,dma_byteenable,dma_waitrequest,rbx_address,rbx_burstcount,rbx_read,rbx_write,rbx_writedata,rbx_byteenable,rbx_waitrequest,rbx_readdata,rbx_readdatavalid,pixclk,d,fval,lval,strobe,reset_n,trigger,sclk,sdata_oe,sdata_in,ext_trigger,shield_step,shield_dir,shield_enable_n);
    
    // Module arguments
    input wire  clk;
    input wire  [18:0] avs_address;
    input wire  avs_read;
    input wire  avs_write;
    input wire  [31:0] avs_writedata;
    input wire  [3:0] avs_byteenable;
    output reg  [31:0] avs_readdata;
    output reg  irq;
    output reg  [28:0] dma_address;
    output reg  [7:0] dma_burstcount;
    output reg  dma_write;
    output reg  [63:0] dma_writedata;
    output reg  [7:0] dma_byteenable;
    input wire  dma_waitrequest;
    output reg  [28:0] rbx_address;
    output reg  [7:0] rbx_burstcount;
    output reg  rbx_read;
    output reg  rbx_write;
    output reg  [63:0] rbx_writedata;
    output reg  [7:0] rbx_byteenable;
    input wire  rbx_waitrequest;
    input wire  [63:0] rbx_readdata;
    input wire  rbx_readdatavalid;
    input wire  pixclk;
    input wire  [11:0] d;
    input wire  fval;
    input wire  lval;
    input wire  strobe;
    output reg  reset_n;
    output reg  trigger;
    output reg  sclk;
    output reg  sdata_oe;
    input wire  sdata_in;
    input wire  ext_trigger;
    output reg  shield_step;
    output reg  shield_dir;
    output reg  shield_enable_n;
    
    // Stub signals
    reg  regs$clock;
    reg  [18:0] regs$avs_address;
    reg  regs$avs_read;
    reg  regs$avs_write;
    reg  [31:0] regs$avs_writedata;
    reg  [3:0] regs$avs_byteenable;
    wire  [31:0] regs$avs_readdata;
    wire  regs$irq;
    wire  [31:0] regs$sys_scratch_value;
    wire  regs$sys_bus_status_unmapped_read;
    wire  regs$sys_bus_status_unmapped_write;
    reg  [31:0] regs$sys_time_lo_cycles;
    reg  [31:0] regs$sys_time_hi_cycles;
    wire  regs$sys_irq_status_frame_done;
    reg  regs$sys_irq_status_frame_done_set;
    wire  regs$sys_irq_status_sequence_done;
    reg  regs$sys_irq_status_sequence_done_set;
    wire  regs$sys_irq_status_dma_error;
    reg  regs$sys_irq_status_dma_error_set;
    wire  regs$sys_irq_status_capture_error;
    reg  regs$sys_irq_status_capture_error_set;
    wire  regs$sys_irq_status_i2c_done;
    reg  regs$sys_irq_status_i2c_done_set;
    wire  regs$sys_irq_status_raybox_done;
    reg  regs$sys_irq_status_raybox_done_set;
    wire  regs$sys_irq_enable_frame_done;
    wire  regs$sys_irq_enable_sequence_done;
    wire  regs$sys_irq_enable_dma_error;
    wire  regs$sys_irq_enable_capture_error;
    wire  regs$sys_irq_enable_i2c_done;
    wire  regs$sys_irq_enable_raybox_done;
    wire  regs$i2c_ctrl_start;
    wire  regs$i2c_ctrl_read;
    wire  [6:0] regs$i2c_target_addr7;
    wire  [7:0] regs$i2c_reg_addr_addr;
    wire  [15:0] regs$i2c_write_data_data;
    reg  [15:0] regs$i2c_read_data_data;
    reg  regs$i2c_status_busy;
    wire  regs$i2c_status_done;
    reg  regs$i2c_status_done_set;
    wire  regs$i2c_status_nack;
    reg  regs$i2c_status_nack_set;
    wire  regs$i2c_status_timeout;
    reg  regs$i2c_status_timeout_set;
    wire  regs$i2c_status_bus_stuck;
    reg  regs$i2c_status_bus_stuck_set;
    wire  regs$i2c_status_refused;
    reg  regs$i2c_status_refused_set;
    wire  [15:0] regs$i2c_clock_div_half_period;
    wire  [23:0] regs$i2c_timeout_cycles;
    wire  regs$i2c_sensor_pins_reset_n;
    reg  regs$i2c_sensor_pins_strobe;
    wire  regs$seq_ctrl_start;
    wire  regs$seq_ctrl_abort;
    wire  regs$seq_ctrl_ext_trigger;
    wire  [3:0] regs$seq_count_exposures;
    reg  regs$seq_status_busy;
    reg  [2:0] regs$seq_status_index;
    reg  regs$seq_status_shield_open;
    wire  regs$seq_status_done;
    reg  regs$seq_status_done_set;
    wire  regs$seq_status_shield_limit_hit;
    reg  regs$seq_status_shield_limit_hit_set;
    wire  regs$seq_status_i2c_error;
    reg  regs$seq_status_i2c_error_set;
    wire  regs$seq_status_refused;
    reg  regs$seq_status_refused_set;
    wire  regs$seq_status_aborted;
    reg  regs$seq_status_aborted_set;
    wire  [31:0] regs$seq_shield_limit_cycles;
    wire  [15:0] regs$seq_shield_steps_steps;
    wire  [23:0] regs$seq_shield_step_period_cycles;
    reg  [31:0] regs$seq_frame_number_value;
    wire  [15:0] regs$seq_trigger_pulse_cycles;
    wire  [19:0] regs$seq_exp_shutter_width_rows$0;
    wire  [19:0] regs$seq_exp_shutter_width_rows$1;
    wire  [19:0] regs$seq_exp_shutter_width_rows$2;
    wire  [19:0] regs$seq_exp_shutter_width_rows$3;
    wire  [19:0] regs$seq_exp_shutter_width_rows$4;
    wire  [19:0] regs$seq_exp_shutter_width_rows$5;
    wire  [19:0] regs$seq_exp_shutter_width_rows$6;
    wire  [19:0] regs$seq_exp_shutter_width_rows$7;
    wire  [12:0] regs$seq_exp_shutter_delay_value$0;
    wire  [12:0] regs$seq_exp_shutter_delay_value$1;
    wire  [12:0] regs$seq_exp_shutter_delay_value$2;
    wire  [12:0] regs$seq_exp_shutter_delay_value$3;
    wire  [12:0] regs$seq_exp_shutter_delay_value$4;
    wire  [12:0] regs$seq_exp_shutter_delay_value$5;
    wire  [12:0] regs$seq_exp_shutter_delay_value$6;
    wire  [12:0] regs$seq_exp_shutter_delay_value$7;
    wire  [15:0] regs$seq_exp_gain_code$0;
    wire  [15:0] regs$seq_exp_gain_code$1;
    wire  [15:0] regs$seq_exp_gain_code$2;
    wire  [15:0] regs$seq_exp_gain_code$3;
    wire  [15:0] regs$seq_exp_gain_code$4;
    wire  [15:0] regs$seq_exp_gain_code$5;
    wire  [15:0] regs$seq_exp_gain_code$6;
    wire  [15:0] regs$seq_exp_gain_code$7;
    wire  regs$capture_ctrl_enable;
    wire  regs$capture_ctrl_raw;
    wire  [11:0] regs$capture_window_width;
    wire  [11:0] regs$capture_window_height;
    reg  regs$capture_status_frame_valid;
    wire  regs$capture_status_line_short;
    reg  regs$capture_status_line_short_set;
    wire  regs$capture_status_line_long;
    reg  regs$capture_status_line_long_set;
    wire  regs$capture_status_frame_short;
    reg  regs$capture_status_frame_short_set;
    wire  regs$capture_status_frame_long;
    reg  regs$capture_status_frame_long_set;
    wire  regs$capture_status_fifo_overflow;
    reg  regs$capture_status_fifo_overflow_set;
    wire  regs$capture_status_pixclk_stopped;
    reg  regs$capture_status_pixclk_stopped_set;
    reg  [11:0] regs$capture_last_frame_pixels;
    reg  [11:0] regs$capture_last_frame_lines;
    reg  [15:0] regs$capture_fifo_high_water_words;
    reg  [31:0] regs$capture_frames_count;
    wire  [1:0] regs$bayer_mode_phase;
    wire  [11:0] regs$bayer_black_level;
    wire  [11:0] regs$bayer_valid_min;
    wire  [11:0] regs$bayer_valid_max;
    wire  [15:0] regs$bayer_weight_r_q2_14;
    wire  [15:0] regs$bayer_weight_g_q2_14;
    wire  [15:0] regs$bayer_weight_b_q2_14;
    wire  regs$dma_ctrl_enable;
    wire  regs$dma_ctrl_reset;
    wire  [31:0] regs$dma_window_base_addr;
    wire  [31:0] regs$dma_window_size_bytes;
    wire  [31:0] regs$dma_slot_stride_bytes;
    wire  [7:0] regs$dma_slots_count;
    reg  regs$dma_status_busy;
    reg  [7:0] regs$dma_status_slot;
    wire  regs$dma_status_frame_done;
    reg  regs$dma_status_frame_done_set;
    wire  regs$dma_status_out_of_window;
    reg  regs$dma_status_out_of_window_set;
    wire  regs$dma_status_overflow;
    reg  regs$dma_status_overflow_set;
    wire  regs$dma_status_bus_timeout;
    reg  regs$dma_status_bus_timeout_set;
    reg  [31:0] regs$dma_frames_written_count;
    wire  [23:0] regs$dma_bus_timeout_cycles;
    wire  regs$raybox_ctrl_start;
    wire  regs$raybox_ctrl_abort;
    wire  [31:0] regs$raybox_work_base_addr;
    wire  [23:0] regs$raybox_work_count_items;
    wire  [31:0] regs$raybox_result_base_addr;
    wire  [31:0] regs$raybox_window_base_addr;
    wire  [31:0] regs$raybox_window_size_bytes;
    reg  regs$raybox_status_busy;
    wire  regs$raybox_status_done;
    reg  regs$raybox_status_done_set;
    wire  regs$raybox_status_bad_descriptor;
    reg  regs$raybox_status_bad_descriptor_set;
    wire  regs$raybox_status_out_of_window;
    reg  regs$raybox_status_out_of_window_set;
    wire  regs$raybox_status_bus_timeout;
    reg  regs$raybox_status_bus_timeout_set;
    reg  [31:0] regs$raybox_tests_done_count;
    reg  [7:0] regs$raybox_info_lanes;
    wire  [23:0] regs$raybox_bus_timeout_cycles;
    wire  regs$sun_ctrl_enable;
    wire  [2:0] regs$sun_ctrl_exposure_index;
    wire  [29:0] regs$sun_threshold_q14;
    wire  [10:0] regs$sun_window_x_min;
    wire  [10:0] regs$sun_window_x_max;
    wire  [10:0] regs$sun_window_y_min;
    wire  [10:0] regs$sun_window_y_max;
    reg  [20:0] regs$sun_count_groups;
    reg  [20:0] regs$sun_over_count_groups;
    reg  [31:0] regs$sun_sum_l_lo_value;
    reg  [31:0] regs$sun_sum_l_hi_value;
    reg  [31:0] regs$sun_sum_xl_lo_value;
    reg  [31:0] regs$sun_sum_xl_hi_value;
    reg  [31:0] regs$sun_sum_yl_lo_value;
    reg  [31:0] regs$sun_sum_yl_hi_value;
    reg  [29:0] regs$sun_max_l_q14;
    reg  [10:0] regs$sun_box_x_min;
    reg  [10:0] regs$sun_box_x_max;
    reg  [10:0] regs$sun_box_y_min;
    reg  [10:0] regs$sun_box_y_max;
    reg  [15:0] regs$sun_frames_count;
    wire  regs$hdr_ctrl_enable;
    wire  regs$hdr_ctrl_new_set;
    wire  [26:0] regs$hdr_min_q11;
    wire  [26:0] regs$hdr_max_q11;
    reg  sensor$clock;
    reg  sensor$i2c_ctrl_start;
    reg  sensor$i2c_ctrl_read;
    reg  [6:0] sensor$i2c_target_addr7;
    reg  [7:0] sensor$i2c_reg_addr_addr;
    reg  [15:0] sensor$i2c_write_data_data;
    reg  [15:0] sensor$i2c_clock_div_half_period;
    reg  [23:0] sensor$i2c_timeout_cycles;
    wire  [15:0] sensor$i2c_read_data_data;
    wire  sensor$i2c_status_busy;
    wire  sensor$i2c_status_done_set;
    wire  sensor$i2c_status_nack_set;
    wire  sensor$i2c_status_timeout_set;
    wire  sensor$i2c_status_bus_stuck_set;
    wire  sensor$i2c_status_refused_set;
    reg  sensor$seq_ctrl_start;
    reg  sensor$seq_ctrl_abort;
    reg  sensor$seq_ctrl_ext_trigger;
    reg  [3:0] sensor$seq_count_exposures;
    reg  [31:0] sensor$seq_shield_limit_cycles;
    reg  [15:0] sensor$seq_shield_steps_steps;
    reg  [23:0] sensor$seq_shield_step_period_cycles;
    reg  [15:0] sensor$seq_trigger_pulse_cycles;
    reg  [19:0] sensor$seq_exp_shutter_width_rows$0;
    reg  [19:0] sensor$seq_exp_shutter_width_rows$1;
    reg  [19:0] sensor$seq_exp_shutter_width_rows$2;
    reg  [19:0] sensor$seq_exp_shutter_width_rows$3;
    reg  [19:0] sensor$seq_exp_shutter_width_rows$4;
    reg  [19:0] sensor$seq_exp_shutter_width_rows$5;
    reg  [19:0] sensor$seq_exp_shutter_width_rows$6;
    reg  [19:0] sensor$seq_exp_shutter_width_rows$7;
    reg  [12:0] sensor$seq_exp_shutter_delay_value$0;
    reg  [12:0] sensor$seq_exp_shutter_delay_value$1;
    reg  [12:0] sensor$seq_exp_shutter_delay_value$2;
    reg  [12:0] sensor$seq_exp_shutter_delay_value$3;
    reg  [12:0] sensor$seq_exp_shutter_delay_value$4;
    reg  [12:0] sensor$seq_exp_shutter_delay_value$5;
    reg  [12:0] sensor$seq_exp_shutter_delay_value$6;
    reg  [12:0] sensor$seq_exp_shutter_delay_value$7;
    reg  [15:0] sensor$seq_exp_gain_code$0;
    reg  [15:0] sensor$seq_exp_gain_code$1;
    reg  [15:0] sensor$seq_exp_gain_code$2;
    reg  [15:0] sensor$seq_exp_gain_code$3;
    reg  [15:0] sensor$seq_exp_gain_code$4;
    reg  [15:0] sensor$seq_exp_gain_code$5;
    reg  [15:0] sensor$seq_exp_gain_code$6;
    reg  [15:0] sensor$seq_exp_gain_code$7;
    wire  sensor$seq_status_busy;
    wire  [2:0] sensor$seq_status_index;
    wire  sensor$seq_status_shield_open;
    wire  sensor$seq_status_done_set;
    wire  sensor$seq_status_shield_limit_hit_set;
    wire  sensor$seq_status_i2c_error_set;
    wire  sensor$seq_status_refused_set;
    wire  sensor$seq_status_aborted_set;
    wire  [31:0] sensor$seq_frame_number_value;
    reg  [63:0] sensor$time_cycles;
    reg  sensor$ext_trigger;
    reg  sensor$frame_valid;
    reg  sensor$scl_in;
    reg  sensor$sda_in;
    wire  sensor$scl_low;
    wire  sensor$sda_low;
    wire  sensor$trigger;
    wire  [2:0] sensor$tag_exposure_index;
    wire  [31:0] sensor$tag_frame_number;
    wire  [63:0] sensor$tag_timestamp;
    wire  sensor$shield_step;
    wire  sensor$shield_dir;
    wire  sensor$shield_enable;
    reg  capture$pixclk;
    reg  capture$clock;
    reg  capture$sensor_frame_valid;
    reg  capture$sensor_line_valid;
    reg  [11:0] capture$sensor_data;
    reg  capture$capture_ctrl_enable;
    reg  capture$capture_ctrl_raw;
    reg  [11:0] capture$capture_window_width;
    reg  [11:0] capture$capture_window_height;
    reg  [1:0] capture$bayer_mode_phase;
    reg  [11:0] capture$bayer_black_level;
    reg  [11:0] capture$bayer_valid_min;
    reg  [11:0] capture$bayer_valid_max;
    reg  [15:0] capture$bayer_weight_r_q2_14;
    reg  [15:0] capture$bayer_weight_g_q2_14;
    reg  [15:0] capture$bayer_weight_b_q2_14;
    reg  capture$dma_ctrl_enable;
    reg  capture$dma_ctrl_reset;
    reg  [31:0] capture$dma_window_base_addr;
    reg  [31:0] capture$dma_window_size_bytes;
    reg  [31:0] capture$dma_slot_stride_bytes;
    reg  [7:0] capture$dma_slots_count;
    reg  [23:0] capture$dma_bus_timeout_cycles;
    reg  capture$sun_ctrl_enable;
    reg  [2:0] capture$sun_ctrl_exposure_index;
    reg  [29:0] capture$sun_threshold_q14;
    reg  [10:0] capture$sun_window_x_min;
    reg  [10:0] capture$sun_window_x_max;
    reg  [10:0] capture$sun_window_y_min;
    reg  [10:0] capture$sun_window_y_max;
    reg  capture$hdr_ctrl_enable;
    reg  capture$hdr_ctrl_new_set;
    reg  [26:0] capture$hdr_min_q11;
    reg  [26:0] capture$hdr_max_q11;
    reg  [2:0] capture$tag_exposure_index;
    reg  [31:0] capture$tag_frame_number;
    reg  [63:0] capture$tag_timestamp;
    wire  capture$capture_status_frame_valid;
    wire  capture$capture_status_line_short_set;
    wire  capture$capture_status_line_long_set;
    wire  capture$capture_status_frame_short_set;
    wire  capture$capture_status_frame_long_set;
    wire  capture$capture_status_fifo_overflow_set;
    wire  capture$capture_status_pixclk_stopped_set;
    wire  [11:0] capture$capture_last_frame_pixels;
    wire  [11:0] capture$capture_last_frame_lines;
    wire  [15:0] capture$capture_fifo_high_water_words;
    wire  [31:0] capture$capture_frames_count;
    wire  capture$dma_status_busy;
    wire  [7:0] capture$dma_status_slot;
    wire  capture$dma_status_frame_done_set;
    wire  capture$dma_status_out_of_window_set;
    wire  capture$dma_status_overflow_set;
    wire  capture$dma_status_bus_timeout_set;
    wire  [31:0] capture$dma_frames_written_count;
    wire  [20:0] capture$sun_count_groups;
    wire  [20:0] capture$sun_over_count_groups;
    wire  [31:0] capture$sun_sum_l_lo_value;
    wire  [31:0] capture$sun_sum_l_hi_value;
    wire  [31:0] capture$sun_sum_xl_lo_value;
    wire  [31:0] capture$sun_sum_xl_hi_value;
    wire  [31:0] capture$sun_sum_yl_lo_value;
    wire  [31:0] capture$sun_sum_yl_hi_value;
    wire  [29:0] capture$sun_max_l_q14;
    wire  [10:0] capture$sun_box_x_min;
    wire  [10:0] capture$sun_box_x_max;
    wire  [10:0] capture$sun_box_y_min;
    wire  [10:0] capture$sun_box_y_max;
    wire  [15:0] capture$sun_frames_count;
    wire  capture$irq_frame_done;
    wire  capture$irq_dma_error;
    wire  capture$irq_capture_error;
    wire  [31:0] capture$avm_address;
    wire  [7:0] capture$avm_burstcount;
    wire  capture$avm_write;
    wire  [63:0] capture$avm_writedata;
    wire  [7:0] capture$avm_byteenable;
    reg  capture$avm_waitrequest;
    reg  raybox$clock;
    reg  raybox$ctrl_start;
    reg  raybox$ctrl_abort;
    reg  [31:0] raybox$work_base_addr;
    reg  [23:0] raybox$work_count_items;
    reg  [31:0] raybox$result_base_addr;
    reg  [31:0] raybox$window_base_addr;
    reg  [31:0] raybox$window_size_bytes;
    reg  [23:0] raybox$bus_timeout_cycles;
    wire  raybox$status_busy;
    wire  raybox$status_done_set;
    wire  raybox$status_bad_descriptor_set;
    wire  raybox$status_out_of_window_set;
    wire  raybox$status_bus_timeout_set;
    wire  [31:0] raybox$tests_done_count;
    wire  [7:0] raybox$info_lanes;
    wire  [28:0] raybox$rbx_address;
    wire  [7:0] raybox$rbx_burstcount;
    wire  raybox$rbx_read;
    wire  raybox$rbx_write;
    wire  [63:0] raybox$rbx_writedata;
    wire  [7:0] raybox$rbx_byteenable;
    reg  raybox$rbx_waitrequest;
    reg  [63:0] raybox$rbx_readdata;
    reg  raybox$rbx_readdatavalid;
    reg  [63:0] time_base$d;
    wire  [63:0] time_base$q;
    reg  time_base$clock;
    reg  strobe_meta$d;
    wire  strobe_meta$q;
    reg  strobe_meta$clock;
    reg  strobe_sync$d;
    wire  strobe_sync$q;
    reg  strobe_sync$clock;
    
    // Sub module instances
    skylux_core$regs regs(
        .clock(regs$clock),
        .avs_address(regs$avs_address),
        .avs_read(regs$avs_read),
        .avs_write(regs$avs_write),
        .avs_writedata(regs$avs_writedata),
        .avs_byteenable(regs$avs_byteenable),
        .avs_readdata(regs$avs_readdata),
        .irq(regs$irq),
        .sys_scratch_value(regs$sys_scratch_value),
        .sys_bus_status_unmapped_read(regs$sys_bus_status_unmapped_read),
        .sys_bus_status_unmapped_write(regs$sys_bus_status_unmapped_write),
        .sys_time_lo_cycles(regs$sys_time_lo_cycles),
        .sys_time_hi_cycles(regs$sys_time_hi_cycles),
        .sys_irq_status_frame_done(regs$sys_irq_status_frame_done),
        .sys_irq_status_frame_done_set(regs$sys_irq_status_frame_done_set),
        .sys_irq_status_sequence_done(regs$sys_irq_status_sequence_done),
        .sys_irq_status_sequence_done_set(regs$sys_irq_status_sequence_done_set),
        .sys_irq_status_dma_error(regs$sys_irq_status_dma_error),
        .sys_irq_status_dma_error_set(regs$sys_irq_status_dma_error_set),
        .sys_irq_status_capture_error(regs$sys_irq_status_capture_error),
        .sys_irq_status_capture_error_set(regs$sys_irq_status_capture_error_set),
        .sys_irq_status_i2c_done(regs$sys_irq_status_i2c_done),
        .sys_irq_status_i2c_done_set(regs$sys_irq_status_i2c_done_set),
        .sys_irq_status_raybox_done(regs$sys_irq_status_raybox_done),
        .sys_irq_status_raybox_done_set(regs$sys_irq_status_raybox_done_set),
        .sys_irq_enable_frame_done(regs$sys_irq_enable_frame_done),
        .sys_irq_enable_sequence_done(regs$sys_irq_enable_sequence_done),
        .sys_irq_enable_dma_error(regs$sys_irq_enable_dma_error),
        .sys_irq_enable_capture_error(regs$sys_irq_enable_capture_error),
        .sys_irq_enable_i2c_done(regs$sys_irq_enable_i2c_done),
        .sys_irq_enable_raybox_done(regs$sys_irq_enable_raybox_done),
        .i2c_ctrl_start(regs$i2c_ctrl_start),
        .i2c_ctrl_read(regs$i2c_ctrl_read),
        .i2c_target_addr7(regs$i2c_target_addr7),
        .i2c_reg_addr_addr(regs$i2c_reg_addr_addr),
        .i2c_write_data_data(regs$i2c_write_data_data),
        .i2c_read_data_data(regs$i2c_read_data_data),
        .i2c_status_busy(regs$i2c_status_busy),
        .i2c_status_done(regs$i2c_status_done),
        .i2c_status_done_set(regs$i2c_status_done_set),
        .i2c_status_nack(regs$i2c_status_nack),
        .i2c_status_nack_set(regs$i2c_status_nack_set),
        .i2c_status_timeout(regs$i2c_status_timeout),
        .i2c_status_timeout_set(regs$i2c_status_timeout_set),
        .i2c_status_bus_stuck(regs$i2c_status_bus_stuck),
        .i2c_status_bus_stuck_set(regs$i2c_status_bus_stuck_set),
        .i2c_status_refused(regs$i2c_status_refused),
        .i2c_status_refused_set(regs$i2c_status_refused_set),
        .i2c_clock_div_half_period(regs$i2c_clock_div_half_period),
        .i2c_timeout_cycles(regs$i2c_timeout_cycles),
        .i2c_sensor_pins_reset_n(regs$i2c_sensor_pins_reset_n),
        .i2c_sensor_pins_strobe(regs$i2c_sensor_pins_strobe),
        .seq_ctrl_start(regs$seq_ctrl_start),
        .seq_ctrl_abort(regs$seq_ctrl_abort),
        .seq_ctrl_ext_trigger(regs$seq_ctrl_ext_trigger),
        .seq_count_exposures(regs$seq_count_exposures),
        .seq_status_busy(regs$seq_status_busy),
        .seq_status_index(regs$seq_status_index),
        .seq_status_shield_open(regs$seq_status_shield_open),
        .seq_status_done(regs$seq_status_done),
        .seq_status_done_set(regs$seq_status_done_set),
        .seq_status_shield_limit_hit(regs$seq_status_shield_limit_hit),
        .seq_status_shield_limit_hit_set(regs$seq_status_shield_limit_hit_set),
        .seq_status_i2c_error(regs$seq_status_i2c_error),
        .seq_status_i2c_error_set(regs$seq_status_i2c_error_set),
        .seq_status_refused(regs$seq_status_refused),
        .seq_status_refused_set(regs$seq_status_refused_set),
        .seq_status_aborted(regs$seq_status_aborted),
        .seq_status_aborted_set(regs$seq_status_aborted_set),
        .seq_shield_limit_cycles(regs$seq_shield_limit_cycles),
        .seq_shield_steps_steps(regs$seq_shield_steps_steps),
        .seq_shield_step_period_cycles(regs$seq_shield_step_period_cycles),
        .seq_frame_number_value(regs$seq_frame_number_value),
        .seq_trigger_pulse_cycles(regs$seq_trigger_pulse_cycles),
        .seq_exp_shutter_width_rows$0(regs$seq_exp_shutter_width_rows$0),
        .seq_exp_shutter_width_rows$1(regs$seq_exp_shutter_width_rows$1),
        .seq_exp_shutter_width_rows$2(regs$seq_exp_shutter_width_rows$2),
        .seq_exp_shutter_width_rows$3(regs$seq_exp_shutter_width_rows$3),
        .seq_exp_shutter_width_rows$4(regs$seq_exp_shutter_width_rows$4),
        .seq_exp_shutter_width_rows$5(regs$seq_exp_shutter_width_rows$5),
        .seq_exp_shutter_width_rows$6(regs$seq_exp_shutter_width_rows$6),
        .seq_exp_shutter_width_rows$7(regs$seq_exp_shutter_width_rows$7),
        .seq_exp_shutter_delay_value$0(regs$seq_exp_shutter_delay_value$0),
        .seq_exp_shutter_delay_value$1(regs$seq_exp_shutter_delay_value$1),
        .seq_exp_shutter_delay_value$2(regs$seq_exp_shutter_delay_value$2),
        .seq_exp_shutter_delay_value$3(regs$seq_exp_shutter_delay_value$3),
        .seq_exp_shutter_delay_value$4(regs$seq_exp_shutter_delay_value$4),
        .seq_exp_shutter_delay_value$5(regs$seq_exp_shutter_delay_value$5),
        .seq_exp_shutter_delay_value$6(regs$seq_exp_shutter_delay_value$6),
        .seq_exp_shutter_delay_value$7(regs$seq_exp_shutter_delay_value$7),
        .seq_exp_gain_code$0(regs$seq_exp_gain_code$0),
        .seq_exp_gain_code$1(regs$seq_exp_gain_code$1),
        .seq_exp_gain_code$2(regs$seq_exp_gain_code$2),
        .seq_exp_gain_code$3(regs$seq_exp_gain_code$3),
        .seq_exp_gain_code$4(regs$seq_exp_gain_code$4),
        .seq_exp_gain_code$5(regs$seq_exp_gain_code$5),
        .seq_exp_gain_code$6(regs$seq_exp_gain_code$6),
        .seq_exp_gain_code$7(regs$seq_exp_gain_code$7),
        .capture_ctrl_enable(regs$capture_ctrl_enable),
        .capture_ctrl_raw(regs$capture_ctrl_raw),
        .capture_window_width(regs$capture_window_width),
        .capture_window_height(regs$capture_window_height),
        .capture_status_frame_valid(regs$capture_status_frame_valid),
        .capture_status_line_short(regs$capture_status_line_short),
        .capture_status_line_short_set(regs$capture_status_line_short_set),
        .capture_status_line_long(regs$capture_status_line_long),
        .capture_status_line_long_set(regs$capture_status_line_long_set),
        .capture_status_frame_short(regs$capture_status_frame_short),
        .capture_status_frame_short_set(regs$capture_status_frame_short_set),
        .capture_status_frame_long(regs$capture_status_frame_long),
        .capture_status_frame_long_set(regs$capture_status_frame_long_set),
        .capture_status_fifo_overflow(regs$capture_status_fifo_overflow),
        .capture_status_fifo_overflow_set(regs$capture_status_fifo_overflow_set),
        .capture_status_pixclk_stopped(regs$capture_status_pixclk_stopped),
        .capture_status_pixclk_stopped_set(regs$capture_status_pixclk_stopped_set),
        .capture_last_frame_pixels(regs$capture_last_frame_pixels),
        .capture_last_frame_lines(regs$capture_last_frame_lines),
        .capture_fifo_high_water_words(regs$capture_fifo_high_water_words),
        .capture_frames_count(regs$capture_frames_count),
        .bayer_mode_phase(regs$bayer_mode_phase),
        .bayer_black_level(regs$bayer_black_level),
        .bayer_valid_min(regs$bayer_valid_min),
        .bayer_valid_max(regs$bayer_valid_max),
        .bayer_weight_r_q2_14(regs$bayer_weight_r_q2_14),
        .bayer_weight_g_q2_14(regs$bayer_weight_g_q2_14),
        .bayer_weight_b_q2_14(regs$bayer_weight_b_q2_14),
        .dma_ctrl_enable(regs$dma_ctrl_enable),
        .dma_ctrl_reset(regs$dma_ctrl_reset),
        .dma_window_base_addr(regs$dma_window_base_addr),
        .dma_window_size_bytes(regs$dma_window_size_bytes),
        .dma_slot_stride_bytes(regs$dma_slot_stride_bytes),
        .dma_slots_count(regs$dma_slots_count),
        .dma_status_busy(regs$dma_status_busy),
        .dma_status_slot(regs$dma_status_slot),
        .dma_status_frame_done(regs$dma_status_frame_done),
        .dma_status_frame_done_set(regs$dma_status_frame_done_set),
        .dma_status_out_of_window(regs$dma_status_out_of_window),
        .dma_status_out_of_window_set(regs$dma_status_out_of_window_set),
        .dma_status_overflow(regs$dma_status_overflow),
        .dma_status_overflow_set(regs$dma_status_overflow_set),
        .dma_status_bus_timeout(regs$dma_status_bus_timeout),
        .dma_status_bus_timeout_set(regs$dma_status_bus_timeout_set),
        .dma_frames_written_count(regs$dma_frames_written_count),
        .dma_bus_timeout_cycles(regs$dma_bus_timeout_cycles),
        .raybox_ctrl_start(regs$raybox_ctrl_start),
        .raybox_ctrl_abort(regs$raybox_ctrl_abort),
        .raybox_work_base_addr(regs$raybox_work_base_addr),
        .raybox_work_count_items(regs$raybox_work_count_items),
        .raybox_result_base_addr(regs$raybox_result_base_addr),
        .raybox_window_base_addr(regs$raybox_window_base_addr),
        .raybox_window_size_bytes(regs$raybox_window_size_bytes),
        .raybox_status_busy(regs$raybox_status_busy),
        .raybox_status_done(regs$raybox_status_done),
        .raybox_status_done_set(regs$raybox_status_done_set),
        .raybox_status_bad_descriptor(regs$raybox_status_bad_descriptor),
        .raybox_status_bad_descriptor_set(regs$raybox_status_bad_descriptor_set),
        .raybox_status_out_of_window(regs$raybox_status_out_of_window),
        .raybox_status_out_of_window_set(regs$raybox_status_out_of_window_set),
        .raybox_status_bus_timeout(regs$raybox_status_bus_timeout),
        .raybox_status_bus_timeout_set(regs$raybox_status_bus_timeout_set),
        .raybox_tests_done_count(regs$raybox_tests_done_count),
        .raybox_info_lanes(regs$raybox_info_lanes),
        .raybox_bus_timeout_cycles(regs$raybox_bus_timeout_cycles),
        .sun_ctrl_enable(regs$sun_ctrl_enable),
        .sun_ctrl_exposure_index(regs$sun_ctrl_exposure_index),
        .sun_threshold_q14(regs$sun_threshold_q14),
        .sun_window_x_min(regs$sun_window_x_min),
        .sun_window_x_max(regs$sun_window_x_max),
        .sun_window_y_min(regs$sun_window_y_min),
        .sun_window_y_max(regs$sun_window_y_max),
        .sun_count_groups(regs$sun_count_groups),
        .sun_over_count_groups(regs$sun_over_count_groups),
        .sun_sum_l_lo_value(regs$sun_sum_l_lo_value),
        .sun_sum_l_hi_value(regs$sun_sum_l_hi_value),
        .sun_sum_xl_lo_value(regs$sun_sum_xl_lo_value),
        .sun_sum_xl_hi_value(regs$sun_sum_xl_hi_value),
        .sun_sum_yl_lo_value(regs$sun_sum_yl_lo_value),
        .sun_sum_yl_hi_value(regs$sun_sum_yl_hi_value),
        .sun_max_l_q14(regs$sun_max_l_q14),
        .sun_box_x_min(regs$sun_box_x_min),
        .sun_box_x_max(regs$sun_box_x_max),
        .sun_box_y_min(regs$sun_box_y_min),
        .sun_box_y_max(regs$sun_box_y_max),
        .sun_frames_count(regs$sun_frames_count),
        .hdr_ctrl_enable(regs$hdr_ctrl_enable),
        .hdr_ctrl_new_set(regs$hdr_ctrl_new_set),
        .hdr_min_q11(regs$hdr_min_q11),
        .hdr_max_q11(regs$hdr_max_q11)
    );
    skylux_core$sensor sensor(
        .clock(sensor$clock),
        .i2c_ctrl_start(sensor$i2c_ctrl_start),
        .i2c_ctrl_read(sensor$i2c_ctrl_read),
        .i2c_target_addr7(sensor$i2c_target_addr7),
        .i2c_reg_addr_addr(sensor$i2c_reg_addr_addr),
        .i2c_write_data_data(sensor$i2c_write_data_data),
        .i2c_clock_div_half_period(sensor$i2c_clock_div_half_period),
        .i2c_timeout_cycles(sensor$i2c_timeout_cycles),
        .i2c_read_data_data(sensor$i2c_read_data_data),
        .i2c_status_busy(sensor$i2c_status_busy),
        .i2c_status_done_set(sensor$i2c_status_done_set),
        .i2c_status_nack_set(sensor$i2c_status_nack_set),
        .i2c_status_timeout_set(sensor$i2c_status_timeout_set),
        .i2c_status_bus_stuck_set(sensor$i2c_status_bus_stuck_set),
        .i2c_status_refused_set(sensor$i2c_status_refused_set),
        .seq_ctrl_start(sensor$seq_ctrl_start),
        .seq_ctrl_abort(sensor$seq_ctrl_abort),
        .seq_ctrl_ext_trigger(sensor$seq_ctrl_ext_trigger),
        .seq_count_exposures(sensor$seq_count_exposures),
        .seq_shield_limit_cycles(sensor$seq_shield_limit_cycles),
        .seq_shield_steps_steps(sensor$seq_shield_steps_steps),
        .seq_shield_step_period_cycles(sensor$seq_shield_step_period_cycles),
        .seq_trigger_pulse_cycles(sensor$seq_trigger_pulse_cycles),
        .seq_exp_shutter_width_rows$0(sensor$seq_exp_shutter_width_rows$0),
        .seq_exp_shutter_width_rows$1(sensor$seq_exp_shutter_width_rows$1),
        .seq_exp_shutter_width_rows$2(sensor$seq_exp_shutter_width_rows$2),
        .seq_exp_shutter_width_rows$3(sensor$seq_exp_shutter_width_rows$3),
        .seq_exp_shutter_width_rows$4(sensor$seq_exp_shutter_width_rows$4),
        .seq_exp_shutter_width_rows$5(sensor$seq_exp_shutter_width_rows$5),
        .seq_exp_shutter_width_rows$6(sensor$seq_exp_shutter_width_rows$6),
        .seq_exp_shutter_width_rows$7(sensor$seq_exp_shutter_width_rows$7),
        .seq_exp_shutter_delay_value$0(sensor$seq_exp_shutter_delay_value$0),
        .seq_exp_shutter_delay_value$1(sensor$seq_exp_shutter_delay_value$1),
        .seq_exp_shutter_delay_value$2(sensor$seq_exp_shutter_delay_value$2),
        .seq_exp_shutter_delay_value$3(sensor$seq_exp_shutter_delay_value$3),
        .seq_exp_shutter_delay_value$4(sensor$seq_exp_shutter_delay_value$4),
        .seq_exp_shutter_delay_value$5(sensor$seq_exp_shutter_delay_value$5),
        .seq_exp_shutter_delay_value$6(sensor$seq_exp_shutter_delay_value$6),
        .seq_exp_shutter_delay_value$7(sensor$seq_exp_shutter_delay_value$7),
        .seq_exp_gain_code$0(sensor$seq_exp_gain_code$0),
        .seq_exp_gain_code$1(sensor$seq_exp_gain_code$1),
        .seq_exp_gain_code$2(sensor$seq_exp_gain_code$2),
        .seq_exp_gain_code$3(sensor$seq_exp_gain_code$3),
        .seq_exp_gain_code$4(sensor$seq_exp_gain_code$4),
        .seq_exp_gain_code$5(sensor$seq_exp_gain_code$5),
        .seq_exp_gain_code$6(sensor$seq_exp_gain_code$6),
        .seq_exp_gain_code$7(sensor$seq_exp_gain_code$7),
        .seq_status_busy(sensor$seq_status_busy),
        .seq_status_index(sensor$seq_status_index),
        .seq_status_shield_open(sensor$seq_status_shield_open),
        .seq_status_done_set(sensor$seq_status_done_set),
        .seq_status_shield_limit_hit_set(sensor$seq_status_shield_limit_hit_set),
        .seq_status_i2c_error_set(sensor$seq_status_i2c_error_set),
        .seq_status_refused_set(sensor$seq_status_refused_set),
        .seq_status_aborted_set(sensor$seq_status_aborted_set),
        .seq_frame_number_value(sensor$seq_frame_number_value),
        .time_cycles(sensor$time_cycles),
        .ext_trigger(sensor$ext_trigger),
        .frame_valid(sensor$frame_valid),
        .scl_in(sensor$scl_in),
        .sda_in(sensor$sda_in),
        .scl_low(sensor$scl_low),
        .sda_low(sensor$sda_low),
        .trigger(sensor$trigger),
        .tag_exposure_index(sensor$tag_exposure_index),
        .tag_frame_number(sensor$tag_frame_number),
        .tag_timestamp(sensor$tag_timestamp),
        .shield_step(sensor$shield_step),
        .shield_dir(sensor$shield_dir),
        .shield_enable(sensor$shield_enable)
    );
    skylux_core$capture capture(
        .pixclk(capture$pixclk),
        .clock(capture$clock),
        .sensor_frame_valid(capture$sensor_frame_valid),
        .sensor_line_valid(capture$sensor_line_valid),
        .sensor_data(capture$sensor_data),
        .capture_ctrl_enable(capture$capture_ctrl_enable),
        .capture_ctrl_raw(capture$capture_ctrl_raw),
        .capture_window_width(capture$capture_window_width),
        .capture_window_height(capture$capture_window_height),
        .bayer_mode_phase(capture$bayer_mode_phase),
        .bayer_black_level(capture$bayer_black_level),
        .bayer_valid_min(capture$bayer_valid_min),
        .bayer_valid_max(capture$bayer_valid_max),
        .bayer_weight_r_q2_14(capture$bayer_weight_r_q2_14),
        .bayer_weight_g_q2_14(capture$bayer_weight_g_q2_14),
        .bayer_weight_b_q2_14(capture$bayer_weight_b_q2_14),
        .dma_ctrl_enable(capture$dma_ctrl_enable),
        .dma_ctrl_reset(capture$dma_ctrl_reset),
        .dma_window_base_addr(capture$dma_window_base_addr),
        .dma_window_size_bytes(capture$dma_window_size_bytes),
        .dma_slot_stride_bytes(capture$dma_slot_stride_bytes),
        .dma_slots_count(capture$dma_slots_count),
        .dma_bus_timeout_cycles(capture$dma_bus_timeout_cycles),
        .sun_ctrl_enable(capture$sun_ctrl_enable),
        .sun_ctrl_exposure_index(capture$sun_ctrl_exposure_index),
        .sun_threshold_q14(capture$sun_threshold_q14),
        .sun_window_x_min(capture$sun_window_x_min),
        .sun_window_x_max(capture$sun_window_x_max),
        .sun_window_y_min(capture$sun_window_y_min),
        .sun_window_y_max(capture$sun_window_y_max),
        .hdr_ctrl_enable(capture$hdr_ctrl_enable),
        .hdr_ctrl_new_set(capture$hdr_ctrl_new_set),
        .hdr_min_q11(capture$hdr_min_q11),
        .hdr_max_q11(capture$hdr_max_q11),
        .tag_exposure_index(capture$tag_exposure_index),
        .tag_frame_number(capture$tag_frame_number),
        .tag_timestamp(capture$tag_timestamp),
        .capture_status_frame_valid(capture$capture_status_frame_valid),
        .capture_status_line_short_set(capture$capture_status_line_short_set),
        .capture_status_line_long_set(capture$capture_status_line_long_set),
        .capture_status_frame_short_set(capture$capture_status_frame_short_set),
        .capture_status_frame_long_set(capture$capture_status_frame_long_set),
        .capture_status_fifo_overflow_set(capture$capture_status_fifo_overflow_set),
        .capture_status_pixclk_stopped_set(capture$capture_status_pixclk_stopped_set),
        .capture_last_frame_pixels(capture$capture_last_frame_pixels),
        .capture_last_frame_lines(capture$capture_last_frame_lines),
        .capture_fifo_high_water_words(capture$capture_fifo_high_water_words),
        .capture_frames_count(capture$capture_frames_count),
        .dma_status_busy(capture$dma_status_busy),
        .dma_status_slot(capture$dma_status_slot),
        .dma_status_frame_done_set(capture$dma_status_frame_done_set),
        .dma_status_out_of_window_set(capture$dma_status_out_of_window_set),
        .dma_status_overflow_set(capture$dma_status_overflow_set),
        .dma_status_bus_timeout_set(capture$dma_status_bus_timeout_set),
        .dma_frames_written_count(capture$dma_frames_written_count),
        .sun_count_groups(capture$sun_count_groups),
        .sun_over_count_groups(capture$sun_over_count_groups),
        .sun_sum_l_lo_value(capture$sun_sum_l_lo_value),
        .sun_sum_l_hi_value(capture$sun_sum_l_hi_value),
        .sun_sum_xl_lo_value(capture$sun_sum_xl_lo_value),
        .sun_sum_xl_hi_value(capture$sun_sum_xl_hi_value),
        .sun_sum_yl_lo_value(capture$sun_sum_yl_lo_value),
        .sun_sum_yl_hi_value(capture$sun_sum_yl_hi_value),
        .sun_max_l_q14(capture$sun_max_l_q14),
        .sun_box_x_min(capture$sun_box_x_min),
        .sun_box_x_max(capture$sun_box_x_max),
        .sun_box_y_min(capture$sun_box_y_min),
        .sun_box_y_max(capture$sun_box_y_max),
        .sun_frames_count(capture$sun_frames_count),
        .irq_frame_done(capture$irq_frame_done),
        .irq_dma_error(capture$irq_dma_error),
        .irq_capture_error(capture$irq_capture_error),
        .avm_address(capture$avm_address),
        .avm_burstcount(capture$avm_burstcount),
        .avm_write(capture$avm_write),
        .avm_writedata(capture$avm_writedata),
        .avm_byteenable(capture$avm_byteenable),
        .avm_waitrequest(capture$avm_waitrequest)
    );
    skylux_core$raybox raybox(
        .clock(raybox$clock),
        .ctrl_start(raybox$ctrl_start),
        .ctrl_abort(raybox$ctrl_abort),
        .work_base_addr(raybox$work_base_addr),
        .work_count_items(raybox$work_count_items),
        .result_base_addr(raybox$result_base_addr),
        .window_base_addr(raybox$window_base_addr),
        .window_size_bytes(raybox$window_size_bytes),
        .bus_timeout_cycles(raybox$bus_timeout_cycles),
        .status_busy(raybox$status_busy),
        .status_done_set(raybox$status_done_set),
        .status_bad_descriptor_set(raybox$status_bad_descriptor_set),
        .status_out_of_window_set(raybox$status_out_of_window_set),
        .status_bus_timeout_set(raybox$status_bus_timeout_set),
        .tests_done_count(raybox$tests_done_count),
        .info_lanes(raybox$info_lanes),
        .rbx_address(raybox$rbx_address),
        .rbx_burstcount(raybox$rbx_burstcount),
        .rbx_read(raybox$rbx_read),
        .rbx_write(raybox$rbx_write),
        .rbx_writedata(raybox$rbx_writedata),
        .rbx_byteenable(raybox$rbx_byteenable),
        .rbx_waitrequest(raybox$rbx_waitrequest),
        .rbx_readdata(raybox$rbx_readdata),
        .rbx_readdatavalid(raybox$rbx_readdatavalid)
    );
    skylux_core$time_base time_base(
        .d(time_base$d),
        .q(time_base$q),
        .clock(time_base$clock)
    );
    skylux_core$strobe_meta strobe_meta(
        .d(strobe_meta$d),
        .q(strobe_meta$q),
        .clock(strobe_meta$clock)
    );
    skylux_core$strobe_sync strobe_sync(
        .d(strobe_sync$d),
        .q(strobe_sync$q),
        .clock(strobe_sync$clock)
    );
    
    // Update code
    always @(*) begin
        regs$clock = clk;
        sensor$clock = clk;
        capture$clock = clk;
        capture$pixclk = pixclk;
        raybox$clock = clk;
        time_base$clock = clk;
        strobe_meta$clock = clk;
        strobe_sync$clock = clk;
        time_base$d = time_base$q;
        strobe_meta$d = strobe_meta$q;
        strobe_sync$d = strobe_sync$q;
        regs$avs_address = avs_address;
        regs$avs_read = avs_read;
        regs$avs_write = avs_write;
        regs$avs_writedata = avs_writedata;
        regs$avs_byteenable = avs_byteenable;
        avs_readdata = regs$avs_readdata;
        irq = regs$irq;
        time_base$d = time_base$q + 32'h1;
        regs$sys_time_lo_cycles = time_base$q[(32'h0)+:(32)];
        regs$sys_time_hi_cycles = time_base$q[(32'h20)+:(32)];
        sensor$time_cycles = time_base$q;
        regs$sys_irq_status_frame_done_set = capture$irq_frame_done;
        regs$sys_irq_status_sequence_done_set = sensor$seq_status_done_set;
        regs$sys_irq_status_dma_error_set = capture$irq_dma_error;
        regs$sys_irq_status_capture_error_set = capture$irq_capture_error;
        regs$sys_irq_status_i2c_done_set = sensor$i2c_status_done_set;
        regs$sys_irq_status_raybox_done_set = raybox$status_done_set;
        capture$sensor_frame_valid = fval;
        capture$sensor_line_valid = lval;
        capture$sensor_data = d;
        sensor$frame_valid = capture$capture_status_frame_valid;
        sensor$ext_trigger = ext_trigger;
        sensor$scl_in = ~sensor$scl_low;
        sensor$sda_in = sdata_in;
        sclk = ~sensor$scl_low;
        sdata_oe = sensor$sda_low;
        trigger = sensor$trigger;
        shield_step = sensor$shield_step;
        shield_dir = sensor$shield_dir;
        shield_enable_n = ~sensor$shield_enable;
        reset_n = regs$i2c_sensor_pins_reset_n;
        strobe_meta$d = strobe;
        strobe_sync$d = strobe_meta$q;
        regs$i2c_sensor_pins_strobe = strobe_sync$q;
        capture$tag_exposure_index = sensor$tag_exposure_index;
        capture$tag_frame_number = sensor$tag_frame_number;
        capture$tag_timestamp = sensor$tag_timestamp;
        dma_address = capture$avm_address[(32'h3)+:(29)];
        dma_burstcount = capture$avm_burstcount;
        dma_write = capture$avm_write;
        dma_writedata = capture$avm_writedata;
        dma_byteenable = capture$avm_byteenable;
        capture$avm_waitrequest = dma_waitrequest;
        rbx_address = raybox$rbx_address;
        rbx_burstcount = raybox$rbx_burstcount;
        rbx_read = raybox$rbx_read;
        rbx_write = raybox$rbx_write;
        rbx_writedata = raybox$rbx_writedata;
        rbx_byteenable = raybox$rbx_byteenable;
        raybox$rbx_waitrequest = rbx_waitrequest;
        raybox$rbx_readdata = rbx_readdata;
        raybox$rbx_readdatavalid = rbx_readdatavalid;
        sensor$i2c_ctrl_start = regs$i2c_ctrl_start;
        sensor$i2c_ctrl_read = regs$i2c_ctrl_read;
        sensor$i2c_target_addr7 = regs$i2c_target_addr7;
        sensor$i2c_reg_addr_addr = regs$i2c_reg_addr_addr;
        sensor$i2c_write_data_data = regs$i2c_write_data_data;
        regs$i2c_read_data_data = sensor$i2c_read_data_data;
        regs$i2c_status_busy = sensor$i2c_status_busy;
        regs$i2c_status_done_set = sensor$i2c_status_done_set;
        regs$i2c_status_nack_set = sensor$i2c_status_nack_set;
        regs$i2c_status_timeout_set = sensor$i2c_status_timeout_set;
        regs$i2c_status_bus_stuck_set = sensor$i2c_status_bus_stuck_set;
        regs$i2c_status_refused_set = sensor$i2c_status_refused_set;
        sensor$i2c_clock_div_half_period = regs$i2c_clock_div_half_period;
        sensor$i2c_timeout_cycles = regs$i2c_timeout_cycles;
        sensor$seq_ctrl_start = regs$seq_ctrl_start;
        sensor$seq_ctrl_abort = regs$seq_ctrl_abort;
        sensor$seq_ctrl_ext_trigger = regs$seq_ctrl_ext_trigger;
        sensor$seq_count_exposures = regs$seq_count_exposures;
        regs$seq_status_busy = sensor$seq_status_busy;
        regs$seq_status_index = sensor$seq_status_index;
        regs$seq_status_shield_open = sensor$seq_status_shield_open;
        regs$seq_status_done_set = sensor$seq_status_done_set;
        regs$seq_status_shield_limit_hit_set = sensor$seq_status_shield_limit_hit_set;
        regs$seq_status_i2c_error_set = sensor$seq_status_i2c_error_set;
        regs$seq_status_refused_set = sensor$seq_status_refused_set;
        regs$seq_status_aborted_set = sensor$seq_status_aborted_set;
        sensor$seq_shield_limit_cycles = regs$seq_shield_limit_cycles;
        sensor$seq_shield_steps_steps = regs$seq_shield_steps_steps;
        sensor$seq_shield_step_period_cycles = regs$seq_shield_step_period_cycles;
        regs$seq_frame_number_value = sensor$seq_frame_number_value;
        sensor$seq_trigger_pulse_cycles = regs$seq_trigger_pulse_cycles;
        sensor$seq_exp_shutter_width_rows$0 = regs$seq_exp_shutter_width_rows$0;
        sensor$seq_exp_shutter_width_rows$1 = regs$seq_exp_shutter_width_rows$1;
        sensor$seq_exp_shutter_width_rows$2 = regs$seq_exp_shutter_width_rows$2;
        sensor$seq_exp_shutter_width_rows$3 = regs$seq_exp_shutter_width_rows$3;
        sensor$seq_exp_shutter_width_rows$4 = regs$seq_exp_shutter_width_rows$4;
        sensor$seq_exp_shutter_width_rows$5 = regs$seq_exp_shutter_width_rows$5;
        sensor$seq_exp_shutter_width_rows$6 = regs$seq_exp_shutter_width_rows$6;
        sensor$seq_exp_shutter_width_rows$7 = regs$seq_exp_shutter_width_rows$7;
        sensor$seq_exp_shutter_delay_value$0 = regs$seq_exp_shutter_delay_value$0;
        sensor$seq_exp_shutter_delay_value$1 = regs$seq_exp_shutter_delay_value$1;
        sensor$seq_exp_shutter_delay_value$2 = regs$seq_exp_shutter_delay_value$2;
        sensor$seq_exp_shutter_delay_value$3 = regs$seq_exp_shutter_delay_value$3;
        sensor$seq_exp_shutter_delay_value$4 = regs$seq_exp_shutter_delay_value$4;
        sensor$seq_exp_shutter_delay_value$5 = regs$seq_exp_shutter_delay_value$5;
        sensor$seq_exp_shutter_delay_value$6 = regs$seq_exp_shutter_delay_value$6;
        sensor$seq_exp_shutter_delay_value$7 = regs$seq_exp_shutter_delay_value$7;
        sensor$seq_exp_gain_code$0 = regs$seq_exp_gain_code$0;
        sensor$seq_exp_gain_code$1 = regs$seq_exp_gain_code$1;
        sensor$seq_exp_gain_code$2 = regs$seq_exp_gain_code$2;
        sensor$seq_exp_gain_code$3 = regs$seq_exp_gain_code$3;
        sensor$seq_exp_gain_code$4 = regs$seq_exp_gain_code$4;
        sensor$seq_exp_gain_code$5 = regs$seq_exp_gain_code$5;
        sensor$seq_exp_gain_code$6 = regs$seq_exp_gain_code$6;
        sensor$seq_exp_gain_code$7 = regs$seq_exp_gain_code$7;
        capture$capture_ctrl_enable = regs$capture_ctrl_enable;
        capture$capture_ctrl_raw = regs$capture_ctrl_raw;
        capture$capture_window_width = regs$capture_window_width;
        capture$capture_window_height = regs$capture_window_height;
        regs$capture_status_frame_valid = capture$capture_status_frame_valid;
        regs$capture_status_line_short_set = capture$capture_status_line_short_set;
        regs$capture_status_line_long_set = capture$capture_status_line_long_set;
        regs$capture_status_frame_short_set = capture$capture_status_frame_short_set;
        regs$capture_status_frame_long_set = capture$capture_status_frame_long_set;
        regs$capture_status_fifo_overflow_set = capture$capture_status_fifo_overflow_set;
        regs$capture_status_pixclk_stopped_set = capture$capture_status_pixclk_stopped_set;
        regs$capture_last_frame_pixels = capture$capture_last_frame_pixels;
        regs$capture_last_frame_lines = capture$capture_last_frame_lines;
        regs$capture_fifo_high_water_words = capture$capture_fifo_high_water_words;
        regs$capture_frames_count = capture$capture_frames_count;
        capture$bayer_mode_phase = regs$bayer_mode_phase;
        capture$bayer_black_level = regs$bayer_black_level;
        capture$bayer_valid_min = regs$bayer_valid_min;
        capture$bayer_valid_max = regs$bayer_valid_max;
        capture$bayer_weight_r_q2_14 = regs$bayer_weight_r_q2_14;
        capture$bayer_weight_g_q2_14 = regs$bayer_weight_g_q2_14;
        capture$bayer_weight_b_q2_14 = regs$bayer_weight_b_q2_14;
        capture$dma_ctrl_enable = regs$dma_ctrl_enable;
        capture$dma_ctrl_reset = regs$dma_ctrl_reset;
        capture$dma_window_base_addr = regs$dma_window_base_addr;
        capture$dma_window_size_bytes = regs$dma_window_size_bytes;
        capture$dma_slot_stride_bytes = regs$dma_slot_stride_bytes;
        capture$dma_slots_count = regs$dma_slots_count;
        regs$dma_status_busy = capture$dma_status_busy;
        regs$dma_status_slot = capture$dma_status_slot;
        regs$dma_status_frame_done_set = capture$dma_status_frame_done_set;
        regs$dma_status_out_of_window_set = capture$dma_status_out_of_window_set;
        regs$dma_status_overflow_set = capture$dma_status_overflow_set;
        regs$dma_status_bus_timeout_set = capture$dma_status_bus_timeout_set;
        regs$dma_frames_written_count = capture$dma_frames_written_count;
        capture$dma_bus_timeout_cycles = regs$dma_bus_timeout_cycles;
        raybox$ctrl_start = regs$raybox_ctrl_start;
        raybox$ctrl_abort = regs$raybox_ctrl_abort;
        raybox$work_base_addr = regs$raybox_work_base_addr;
        raybox$work_count_items = regs$raybox_work_count_items;
        raybox$result_base_addr = regs$raybox_result_base_addr;
        raybox$window_base_addr = regs$raybox_window_base_addr;
        raybox$window_size_bytes = regs$raybox_window_size_bytes;
        regs$raybox_status_busy = raybox$status_busy;
        regs$raybox_status_done_set = raybox$status_done_set;
        regs$raybox_status_bad_descriptor_set = raybox$status_bad_descriptor_set;
        regs$raybox_status_out_of_window_set = raybox$status_out_of_window_set;
        regs$raybox_status_bus_timeout_set = raybox$status_bus_timeout_set;
        regs$raybox_tests_done_count = raybox$tests_done_count;
        regs$raybox_info_lanes = raybox$info_lanes;
        raybox$bus_timeout_cycles = regs$raybox_bus_timeout_cycles;
        capture$sun_ctrl_enable = regs$sun_ctrl_enable;
        capture$sun_ctrl_exposure_index = regs$sun_ctrl_exposure_index;
        capture$sun_threshold_q14 = regs$sun_threshold_q14;
        capture$sun_window_x_min = regs$sun_window_x_min;
        capture$sun_window_x_max = regs$sun_window_x_max;
        capture$sun_window_y_min = regs$sun_window_y_min;
        capture$sun_window_y_max = regs$sun_window_y_max;
        regs$sun_count_groups = capture$sun_count_groups;
        regs$sun_over_count_groups = capture$sun_over_count_groups;
        regs$sun_sum_l_lo_value = capture$sun_sum_l_lo_value;
        regs$sun_sum_l_hi_value = capture$sun_sum_l_hi_value;
        regs$sun_sum_xl_lo_value = capture$sun_sum_xl_lo_value;
        regs$sun_sum_xl_hi_value = capture$sun_sum_xl_hi_value;
        regs$sun_sum_yl_lo_value = capture$sun_sum_yl_lo_value;
        regs$sun_sum_yl_hi_value = capture$sun_sum_yl_hi_value;
        regs$sun_max_l_q14 = capture$sun_max_l_q14;
        regs$sun_box_x_min = capture$sun_box_x_min;
        regs$sun_box_x_max = capture$sun_box_x_max;
        regs$sun_box_y_min = capture$sun_box_y_min;
        regs$sun_box_y_max = capture$sun_box_y_max;
        regs$sun_frames_count = capture$sun_frames_count;
        capture$hdr_ctrl_enable = regs$hdr_ctrl_enable;
        capture$hdr_ctrl_new_set = regs$hdr_ctrl_new_set;
        capture$hdr_min_q11 = regs$hdr_min_q11;
        capture$hdr_max_q11 = regs$hdr_max_q11;
    end
    
endmodule // top


module skylux_core$capture(pixclk,clock,sensor_frame_valid,sensor_line_valid,sensor_data,capture_ctrl_enable,capture_ctrl_raw,capture_window_width,capture_window_height,bayer_mode_phase,bayer_black_level,bayer_valid_min,bayer_valid_max,bayer_weight_r_q2_14,bayer_weight_g_q2_14,bayer_weight_b_q2_14,dma_ctrl_enable,dma_ctrl_reset,dma_window_base_addr,dma_window_size_bytes,dma_slot_stride_bytes,dma_slots_count,dma_bus_timeout_cycles,sun_ctrl_enable,sun_ctrl_exposure_index,sun_threshold_q14,sun_window_x_min,sun_window_x_max,sun_window_y_min,sun_window_y_max,hdr_ctrl_enable,hdr_ctrl_new_set,hdr_min_q11,hdr_max_q11,tag_exposure_index,tag_frame_number,tag_timestamp,capture_status_frame_valid,capture_status_line_short_set,capture_status_line_long_set,capture_status_frame_short_set,capture_status_frame_long_set,capture_status_fifo_overflow_set,capture_status_pixclk_stopped_set,capture_last_frame_pixels,capture_last_frame_lines,capture_fifo_high_water_words,capture_frames_count,dma_status_busy,dma_status_slot,dma_status_frame_done_set,dma_status_out_of_window_set,dma_status_overflow_set,dma_status_bus_timeout_set,dma_frames_written_count,sun_count_groups,sun_over_count_groups,sun_sum_l_lo_value,sun_sum_l_hi_value,sun_sum_xl_lo_value,sun_sum_xl_hi_value,sun_sum_yl_lo_value,sun_sum_yl_hi_value,sun_max_l_q14,sun_box_x_min,sun_box_x_max,sun_box_y_min,sun_box_y_max,sun_frames_count,irq_frame_done,irq_dma_error,irq_capture_error,avm_address,avm_burstcount,avm_write,avm_writedata,avm_byteenable,avm_waitrequest);
    
    // Module arguments
    input wire  pixclk;
    input wire  clock;
    input wire  sensor_frame_valid;
    input wire  sensor_line_valid;
    input wire  [11:0] sensor_data;
    input wire  capture_ctrl_enable;
    input wire  capture_ctrl_raw;
    input wire  [11:0] capture_window_width;
    input wire  [11:0] capture_window_height;
    input wire  [1:0] bayer_mode_phase;
    input wire  [11:0] bayer_black_level;
    input wire  [11:0] bayer_valid_min;
    input wire  [11:0] bayer_valid_max;
    input wire  [15:0] bayer_weight_r_q2_14;
    input wire  [15:0] bayer_weight_g_q2_14;
    input wire  [15:0] bayer_weight_b_q2_14;
    input wire  dma_ctrl_enable;
    input wire  dma_ctrl_reset;
    input wire  [31:0] dma_window_base_addr;
    input wire  [31:0] dma_window_size_bytes;
    input wire  [31:0] dma_slot_stride_bytes;
    input wire  [7:0] dma_slots_count;
    input wire  [23:0] dma_bus_timeout_cycles;
    input wire  sun_ctrl_enable;
    input wire  [2:0] sun_ctrl_exposure_index;
    input wire  [29:0] sun_threshold_q14;
    input wire  [10:0] sun_window_x_min;
    input wire  [10:0] sun_window_x_max;
    input wire  [10:0] sun_window_y_min;
    input wire  [10:0] sun_window_y_max;
    input wire  hdr_ctrl_enable;
    input wire  hdr_ctrl_new_set;
    input wire  [26:0] hdr_min_q11;
    input wire  [26:0] hdr_max_q11;
    input wire  [2:0] tag_exposure_index;
    input wire  [31:0] tag_frame_number;
    input wire  [63:0] tag_timestamp;
    output reg  capture_status_frame_valid;
    output reg  capture_status_line_short_set;
    output reg  capture_status_line_long_set;
    output reg  capture_status_frame_short_set;
    output reg  capture_status_frame_long_set;
    output reg  capture_status_fifo_overflow_set;
    output reg  capture_status_pixclk_stopped_set;
    output reg  [11:0] capture_last_frame_pixels;
    output reg  [11:0] capture_last_frame_lines;
    output reg  [15:0] capture_fifo_high_water_words;
    output reg  [31:0] capture_frames_count;
    output reg  dma_status_busy;
    output reg  [7:0] dma_status_slot;
    output reg  dma_status_frame_done_set;
    output reg  dma_status_out_of_window_set;
    output reg  dma_status_overflow_set;
    output reg  dma_status_bus_timeout_set;
    output reg  [31:0] dma_frames_written_count;
    output reg  [20:0] sun_count_groups;
    output reg  [20:0] sun_over_count_groups;
    output reg  [31:0] sun_sum_l_lo_value;
    output reg  [31:0] sun_sum_l_hi_value;
    output reg  [31:0] sun_sum_xl_lo_value;
    output reg  [31:0] sun_sum_xl_hi_value;
    output reg  [31:0] sun_sum_yl_lo_value;
    output reg  [31:0] sun_sum_yl_hi_value;
    output reg  [29:0] sun_max_l_q14;
    output reg  [10:0] sun_box_x_min;
    output reg  [10:0] sun_box_x_max;
    output reg  [10:0] sun_box_y_min;
    output reg  [10:0] sun_box_y_max;
    output reg  [15:0] sun_frames_count;
    output reg  irq_frame_done;
    output reg  irq_dma_error;
    output reg  irq_capture_error;
    output reg  [31:0] avm_address;
    output reg  [7:0] avm_burstcount;
    output reg  avm_write;
    output reg  [63:0] avm_writedata;
    output reg  [7:0] avm_byteenable;
    input wire  avm_waitrequest;
    
    // Stub signals
    reg  capture$clock;
    reg  capture$frame_valid;
    reg  capture$line_valid;
    reg  [11:0] capture$data;
    reg  capture$enable;
    reg  [11:0] capture$width;
    reg  [11:0] capture$height;
    wire  [11:0] capture$pixel;
    wire  capture$pixel_valid;
    wire  capture$line_start;
    wire  capture$frame_start;
    reg  [31:0] capture$word;
    reg  capture$word_valid;
    reg  [7:0] capture$fifo_fill;
    wire  [33:0] capture$fifo_data;
    wire  capture$fifo_write;
    wire  capture$frame_valid_registered;
    wire  capture$heartbeat;
    reg  grouper$clock;
    reg  [11:0] grouper$pixel;
    reg  grouper$pixel_valid;
    reg  grouper$line_start;
    reg  grouper$frame_start;
    reg  [1:0] grouper$phase;
    reg  [11:0] grouper$black;
    reg  [11:0] grouper$valid_min;
    reg  [11:0] grouper$valid_max;
    reg  [15:0] grouper$weight_r;
    reg  [15:0] grouper$weight_g;
    reg  [15:0] grouper$weight_b;
    reg  grouper$raw;
    wire  [31:0] grouper$word;
    wire  grouper$word_valid;
    reg  fifo$read;
    wire  [33:0] fifo$data_out;
    wire  fifo$empty;
    wire  fifo$almost_empty;
    wire  fifo$underflow;
    reg  fifo$read_clock;
    wire  [7:0] fifo$read_fill;
    reg  fifo$write;
    reg  [33:0] fifo$data_in;
    wire  fifo$full;
    wire  fifo$almost_full;
    wire  fifo$overflow;
    reg  fifo$write_clock;
    wire  [7:0] fifo$write_fill;
    reg  ingest$clock;
    reg  [33:0] ingest$fifo_data;
    reg  ingest$fifo_empty;
    reg  [7:0] ingest$fifo_fill;
    wire  ingest$fifo_read;
    reg  ingest$frame_valid_async;
    reg  ingest$heartbeat_async;
    reg  ingest$enable;
    reg  ingest$raw;
    reg  [2:0] ingest$tag_exposure_index;
    reg  [31:0] ingest$tag_frame_number;
    reg  [63:0] ingest$tag_timestamp;
    reg  ingest$hdr_enable;
    reg  ingest$hdr_new_set;
    reg  [26:0] ingest$hdr_min_q11;
    reg  [26:0] ingest$hdr_max_q11;
    reg  ingest$writer_idle;
    reg  ingest$frame_closed;
    reg  ingest$beat_room;
    wire  ingest$beat_push;
    wire  [63:0] ingest$beat_data;
    wire  [7:0] ingest$beat_byteenable;
    wire  ingest$frame_open;
    wire  ingest$frame_ended;
    wire  [31:0] ingest$desc_frame_number;
    wire  [63:0] ingest$desc_timestamp;
    wire  [31:0] ingest$desc_info;
    wire  [31:0] ingest$desc_geometry;
    wire  [31:0] ingest$desc_words;
    wire  [31:0] ingest$desc_checksum;
    wire  ingest$capture_status_frame_valid;
    wire  ingest$capture_status_line_short_set;
    wire  ingest$capture_status_line_long_set;
    wire  ingest$capture_status_frame_short_set;
    wire  ingest$capture_status_frame_long_set;
    wire  ingest$capture_status_fifo_overflow_set;
    wire  ingest$capture_status_pixclk_stopped_set;
    wire  [11:0] ingest$capture_last_frame_pixels;
    wire  [11:0] ingest$capture_last_frame_lines;
    wire  [15:0] ingest$capture_fifo_high_water_words;
    wire  [31:0] ingest$capture_frames_count;
    wire  ingest$dma_status_overflow_set;
    wire  ingest$taken_valid;
    wire  [31:0] ingest$taken_word;
    wire  ingest$taken_first;
    wire  [2:0] ingest$taken_exposure_index;
    reg  writer$clock;
    reg  writer$restart;
    reg  [31:0] writer$window_base;
    reg  [31:0] writer$window_size;
    reg  [31:0] writer$slot_stride;
    reg  [7:0] writer$slots;
    reg  [23:0] writer$bus_timeout;
    reg  writer$beat_push;
    reg  [63:0] writer$beat_data;
    reg  [7:0] writer$beat_byteenable;
    reg  writer$frame_open;
    reg  writer$frame_ended;
    reg  [31:0] writer$desc_frame_number;
    reg  [63:0] writer$desc_timestamp;
    reg  [31:0] writer$desc_info;
    reg  [31:0] writer$desc_geometry;
    reg  [31:0] writer$desc_words;
    reg  [31:0] writer$desc_checksum;
    wire  writer$writer_idle;
    wire  writer$frame_closed;
    wire  writer$beat_room;
    wire  writer$dma_status_busy;
    wire  [7:0] writer$dma_status_slot;
    wire  writer$dma_status_frame_done_set;
    wire  writer$dma_status_out_of_window_set;
    wire  writer$dma_status_bus_timeout_set;
    wire  [31:0] writer$dma_frames_written_count;
    wire  [31:0] writer$avm_address;
    wire  [7:0] writer$avm_burstcount;
    wire  writer$avm_write;
    wire  [63:0] writer$avm_writedata;
    wire  [7:0] writer$avm_byteenable;
    reg  writer$avm_waitrequest;
    reg  sun$clock;
    reg  sun$word_valid;
    reg  [31:0] sun$word;
    reg  sun$frame_start;
    reg  sun$armed;
    reg  [10:0] sun$groups_per_line;
    reg  [29:0] sun$threshold_q14;
    reg  [10:0] sun$x_min;
    reg  [10:0] sun$x_max;
    reg  [10:0] sun$y_min;
    reg  [10:0] sun$y_max;
    wire  [20:0] sun$sun_count;
    wire  [20:0] sun$over_count;
    wire  [63:0] sun$sum_l;
    wire  [63:0] sun$sum_xl;
    wire  [63:0] sun$sum_yl;
    wire  [29:0] sun$max_l;
    wire  [10:0] sun$min_x;
    wire  [10:0] sun$max_x;
    wire  [10:0] sun$min_y;
    wire  [10:0] sun$max_y;
    wire  [15:0] sun$armed_frames;
    
    // Sub module instances
    skylux_core$capture$capture capture(
        .clock(capture$clock),
        .frame_valid(capture$frame_valid),
        .line_valid(capture$line_valid),
        .data(capture$data),
        .enable(capture$enable),
        .width(capture$width),
        .height(capture$height),
        .pixel(capture$pixel),
        .pixel_valid(capture$pixel_valid),
        .line_start(capture$line_start),
        .frame_start(capture$frame_start),
        .word(capture$word),
        .word_valid(capture$word_valid),
        .fifo_fill(capture$fifo_fill),
        .fifo_data(capture$fifo_data),
        .fifo_write(capture$fifo_write),
        .frame_valid_registered(capture$frame_valid_registered),
        .heartbeat(capture$heartbeat)
    );
    skylux_core$capture$grouper grouper(
        .clock(grouper$clock),
        .pixel(grouper$pixel),
        .pixel_valid(grouper$pixel_valid),
        .line_start(grouper$line_start),
        .frame_start(grouper$frame_start),
        .phase(grouper$phase),
        .black(grouper$black),
        .valid_min(grouper$valid_min),
        .valid_max(grouper$valid_max),
        .weight_r(grouper$weight_r),
        .weight_g(grouper$weight_g),
        .weight_b(grouper$weight_b),
        .raw(grouper$raw),
        .word(grouper$word),
        .word_valid(grouper$word_valid)
    );
    skylux_core$capture$fifo fifo(
        .read(fifo$read),
        .data_out(fifo$data_out),
        .empty(fifo$empty),
        .almost_empty(fifo$almost_empty),
        .underflow(fifo$underflow),
        .read_clock(fifo$read_clock),
        .read_fill(fifo$read_fill),
        .write(fifo$write),
        .data_in(fifo$data_in),
        .full(fifo$full),
        .almost_full(fifo$almost_full),
        .overflow(fifo$overflow),
        .write_clock(fifo$write_clock),
        .write_fill(fifo$write_fill)
    );
    skylux_core$capture$ingest ingest(
        .clock(ingest$clock),
        .fifo_data(ingest$fifo_data),
        .fifo_empty(ingest$fifo_empty),
        .fifo_fill(ingest$fifo_fill),
        .fifo_read(ingest$fifo_read),
        .frame_valid_async(ingest$frame_valid_async),
        .heartbeat_async(ingest$heartbeat_async),
        .enable(ingest$enable),
        .raw(ingest$raw),
        .tag_exposure_index(ingest$tag_exposure_index),
        .tag_frame_number(ingest$tag_frame_number),
        .tag_timestamp(ingest$tag_timestamp),
        .hdr_enable(ingest$hdr_enable),
        .hdr_new_set(ingest$hdr_new_set),
        .hdr_min_q11(ingest$hdr_min_q11),
        .hdr_max_q11(ingest$hdr_max_q11),
        .writer_idle(ingest$writer_idle),
        .frame_closed(ingest$frame_closed),
        .beat_room(ingest$beat_room),
        .beat_push(ingest$beat_push),
        .beat_data(ingest$beat_data),
        .beat_byteenable(ingest$beat_byteenable),
        .frame_open(ingest$frame_open),
        .frame_ended(ingest$frame_ended),
        .desc_frame_number(ingest$desc_frame_number),
        .desc_timestamp(ingest$desc_timestamp),
        .desc_info(ingest$desc_info),
        .desc_geometry(ingest$desc_geometry),
        .desc_words(ingest$desc_words),
        .desc_checksum(ingest$desc_checksum),
        .capture_status_frame_valid(ingest$capture_status_frame_valid),
        .capture_status_line_short_set(ingest$capture_status_line_short_set),
        .capture_status_line_long_set(ingest$capture_status_line_long_set),
        .capture_status_frame_short_set(ingest$capture_status_frame_short_set),
        .capture_status_frame_long_set(ingest$capture_status_frame_long_set),
        .capture_status_fifo_overflow_set(ingest$capture_status_fifo_overflow_set),
        .capture_status_pixclk_stopped_set(ingest$capture_status_pixclk_stopped_set),
        .capture_last_frame_pixels(ingest$capture_last_frame_pixels),
        .capture_last_frame_lines(ingest$capture_last_frame_lines),
        .capture_fifo_high_water_words(ingest$capture_fifo_high_water_words),
        .capture_frames_count(ingest$capture_frames_count),
        .dma_status_overflow_set(ingest$dma_status_overflow_set),
        .taken_valid(ingest$taken_valid),
        .taken_word(ingest$taken_word),
        .taken_first(ingest$taken_first),
        .taken_exposure_index(ingest$taken_exposure_index)
    );
    skylux_core$capture$writer writer(
        .clock(writer$clock),
        .restart(writer$restart),
        .window_base(writer$window_base),
        .window_size(writer$window_size),
        .slot_stride(writer$slot_stride),
        .slots(writer$slots),
        .bus_timeout(writer$bus_timeout),
        .beat_push(writer$beat_push),
        .beat_data(writer$beat_data),
        .beat_byteenable(writer$beat_byteenable),
        .frame_open(writer$frame_open),
        .frame_ended(writer$frame_ended),
        .desc_frame_number(writer$desc_frame_number),
        .desc_timestamp(writer$desc_timestamp),
        .desc_info(writer$desc_info),
        .desc_geometry(writer$desc_geometry),
        .desc_words(writer$desc_words),
        .desc_checksum(writer$desc_checksum),
        .writer_idle(writer$writer_idle),
        .frame_closed(writer$frame_closed),
        .beat_room(writer$beat_room),
        .dma_status_busy(writer$dma_status_busy),
        .dma_status_slot(writer$dma_status_slot),
        .dma_status_frame_done_set(writer$dma_status_frame_done_set),
        .dma_status_out_of_window_set(writer$dma_status_out_of_window_set),
        .dma_status_bus_timeout_set(writer$dma_status_bus_timeout_set),
        .dma_frames_written_count(writer$dma_frames_written_count),
        .avm_address(writer$avm_address),
        .avm_burstcount(writer$avm_burstcount),
        .avm_write(writer$avm_write),
        .avm_writedata(writer$avm_writedata),
        .avm_byteenable(writer$avm_byteenable),
        .avm_waitrequest(writer$avm_waitrequest)
    );
    skylux_core$capture$sun sun(
        .clock(sun$clock),
        .word_valid(sun$word_valid),
        .word(sun$word),
        .frame_start(sun$frame_start),
        .armed(sun$armed),
        .groups_per_line(sun$groups_per_line),
        .threshold_q14(sun$threshold_q14),
        .x_min(sun$x_min),
        .x_max(sun$x_max),
        .y_min(sun$y_min),
        .y_max(sun$y_max),
        .sun_count(sun$sun_count),
        .over_count(sun$over_count),
        .sum_l(sun$sum_l),
        .sum_xl(sun$sum_xl),
        .sum_yl(sun$sum_yl),
        .max_l(sun$max_l),
        .min_x(sun$min_x),
        .max_x(sun$max_x),
        .min_y(sun$min_y),
        .max_y(sun$max_y),
        .armed_frames(sun$armed_frames)
    );
    
    // Update code
    always @(*) begin
        capture$clock = pixclk;
        grouper$clock = pixclk;
        fifo$write_clock = pixclk;
        capture$frame_valid = sensor_frame_valid;
        capture$line_valid = sensor_line_valid;
        capture$data = sensor_data;
        capture$enable = capture_ctrl_enable;
        capture$width = capture_window_width;
        capture$height = capture_window_height;
        grouper$pixel = capture$pixel;
        grouper$pixel_valid = capture$pixel_valid;
        grouper$line_start = capture$line_start;
        grouper$frame_start = capture$frame_start;
        grouper$phase = bayer_mode_phase;
        grouper$black = bayer_black_level;
        grouper$valid_min = bayer_valid_min;
        grouper$valid_max = bayer_valid_max;
        grouper$weight_r = bayer_weight_r_q2_14;
        grouper$weight_g = bayer_weight_g_q2_14;
        grouper$weight_b = bayer_weight_b_q2_14;
        grouper$raw = capture_ctrl_raw;
        capture$word = grouper$word;
        capture$word_valid = grouper$word_valid;
        capture$fifo_fill = fifo$write_fill;
        fifo$data_in = capture$fifo_data;
        fifo$write = capture$fifo_write;
        fifo$read_clock = clock;
        ingest$clock = clock;
        writer$clock = clock;
        ingest$fifo_data = fifo$data_out;
        ingest$fifo_empty = fifo$empty;
        ingest$fifo_fill = fifo$read_fill;
        fifo$read = ingest$fifo_read;
        ingest$frame_valid_async = capture$frame_valid_registered;
        ingest$heartbeat_async = capture$heartbeat;
        ingest$enable = dma_ctrl_enable;
        ingest$raw = capture_ctrl_raw;
        ingest$tag_exposure_index = tag_exposure_index;
        ingest$tag_frame_number = tag_frame_number;
        ingest$tag_timestamp = tag_timestamp;
        ingest$writer_idle = writer$writer_idle;
        ingest$frame_closed = writer$frame_closed;
        ingest$beat_room = writer$beat_room;
        ingest$hdr_enable = hdr_ctrl_enable;
        ingest$hdr_new_set = hdr_ctrl_new_set;
        ingest$hdr_min_q11 = hdr_min_q11;
        ingest$hdr_max_q11 = hdr_max_q11;
        writer$restart = dma_ctrl_reset;
        writer$window_base = dma_window_base_addr;
        writer$window_size = dma_window_size_bytes;
        writer$slot_stride = dma_slot_stride_bytes;
        writer$slots = dma_slots_count;
        writer$bus_timeout = dma_bus_timeout_cycles;
        writer$beat_push = ingest$beat_push;
        writer$beat_data = ingest$beat_data;
        writer$beat_byteenable = ingest$beat_byteenable;
        writer$frame_open = ingest$frame_open;
        writer$frame_ended = ingest$frame_ended;
        writer$desc_frame_number = ingest$desc_frame_number;
        writer$desc_timestamp = ingest$desc_timestamp;
        writer$desc_info = ingest$desc_info;
        writer$desc_geometry = ingest$desc_geometry;
        writer$desc_words = ingest$desc_words;
        writer$desc_checksum = ingest$desc_checksum;
        writer$avm_waitrequest = avm_waitrequest;
        capture_status_frame_valid = ingest$capture_status_frame_valid;
        capture_status_line_short_set = ingest$capture_status_line_short_set;
        capture_status_line_long_set = ingest$capture_status_line_long_set;
        capture_status_frame_short_set = ingest$capture_status_frame_short_set;
        capture_status_frame_long_set = ingest$capture_status_frame_long_set;
        capture_status_fifo_overflow_set = ingest$capture_status_fifo_overflow_set;
        capture_status_pixclk_stopped_set = ingest$capture_status_pixclk_stopped_set;
        capture_last_frame_pixels = ingest$capture_last_frame_pixels;
        capture_last_frame_lines = ingest$capture_last_frame_lines;
        capture_fifo_high_water_words = ingest$capture_fifo_high_water_words;
        capture_frames_count = ingest$capture_frames_count;
        dma_status_busy = writer$dma_status_busy;
        dma_status_slot = writer$dma_status_slot;
        dma_status_frame_done_set = writer$dma_status_frame_done_set;
        dma_status_out_of_window_set = writer$dma_status_out_of_window_set;
        dma_status_overflow_set = ingest$dma_status_overflow_set;
        dma_status_bus_timeout_set = writer$dma_status_bus_timeout_set;
        dma_frames_written_count = writer$dma_frames_written_count;
        irq_frame_done = writer$dma_status_frame_done_set;
        irq_dma_error = writer$dma_status_out_of_window_set | writer$dma_status_bus_timeout_set | ingest$dma_status_overflow_set;
        irq_capture_error = ingest$capture_status_line_short_set | ingest$capture_status_line_long_set | ingest$capture_status_frame_short_set | ingest$capture_status_frame_long_set | ingest$capture_status_fifo_overflow_set | ingest$capture_status_pixclk_stopped_set;
        sun$clock = clock;
        sun$word_valid = ingest$taken_valid;
        sun$word = ingest$taken_word;
        sun$frame_start = ingest$taken_first;
        sun$armed = sun_ctrl_enable & ~capture_ctrl_raw & (ingest$taken_exposure_index == sun_ctrl_exposure_index);
        sun$groups_per_line = capture_window_width[(32'h1)+:(11)];
        sun$threshold_q14 = sun_threshold_q14;
        sun$x_min = sun_window_x_min;
        sun$x_max = sun_window_x_max;
        sun$y_min = sun_window_y_min;
        sun$y_max = sun_window_y_max;
        sun_count_groups = sun$sun_count;
        sun_over_count_groups = sun$over_count;
        sun_sum_l_lo_value = sun$sum_l[(32'h0)+:(32)];
        sun_sum_l_hi_value = sun$sum_l[(32'h20)+:(32)];
        sun_sum_xl_lo_value = sun$sum_xl[(32'h0)+:(32)];
        sun_sum_xl_hi_value = sun$sum_xl[(32'h20)+:(32)];
        sun_sum_yl_lo_value = sun$sum_yl[(32'h0)+:(32)];
        sun_sum_yl_hi_value = sun$sum_yl[(32'h20)+:(32)];
        sun_max_l_q14 = sun$max_l;
        sun_box_x_min = sun$min_x;
        sun_box_x_max = sun$max_x;
        sun_box_y_min = sun$min_y;
        sun_box_y_max = sun$max_y;
        sun_frames_count = sun$armed_frames;
        avm_address = writer$avm_address;
        avm_burstcount = writer$avm_burstcount;
        avm_write = writer$avm_write;
        avm_writedata = writer$avm_writedata;
        avm_byteenable = writer$avm_byteenable;
    end
    
endmodule // skylux_core$capture


module skylux_core$capture$capture(clock,frame_valid,line_valid,data,enable,width,height,pixel,pixel_valid,line_start,frame_start,word,word_valid,fifo_fill,fifo_data,fifo_write,frame_valid_registered,heartbeat);
    
    // Module arguments
    input wire  clock;
    input wire  frame_valid;
    input wire  line_valid;
    input wire  [11:0] data;
    input wire  enable;
    input wire  [11:0] width;
    input wire  [11:0] height;
    output reg  [11:0] pixel;
    output reg  pixel_valid;
    output reg  line_start;
    output reg  frame_start;
    input wire  [31:0] word;
    input wire  word_valid;
    input wire  [7:0] fifo_fill;
    output reg  [33:0] fifo_data;
    output reg  fifo_write;
    output reg  frame_valid_registered;
    output reg  heartbeat;
    
    // Constant declarations
    localparam  data_limit = 8'h7c;
    localparam  start_limit = 8'h7e;
    localparam  end_delay = 3'b111;
    localparam  start_marker = 34'h100000000;
    localparam  end_marker = 34'h300000000;
    
    // Stub signals
    reg  enable_meta$d;
    wire  enable_meta$q;
    reg  enable_meta$clock;
    reg  enable_sync$d;
    wire  enable_sync$q;
    reg  enable_sync$clock;
    reg  fv_r$d;
    wire  fv_r$q;
    reg  fv_r$clock;
    reg  lv_r$d;
    wire  lv_r$q;
    reg  lv_r$clock;
    reg  [11:0] d_r$d;
    wire  [11:0] d_r$q;
    reg  d_r$clock;
    reg  prev_fv$d;
    wire  prev_fv$q;
    reg  prev_fv$clock;
    reg  prev_active$d;
    wire  prev_active$q;
    reg  prev_active$clock;
    reg  [3:0] heartbeat_count$d;
    wire  [3:0] heartbeat_count$q;
    reg  heartbeat_count$clock;
    reg  in_frame$d;
    wire  in_frame$q;
    reg  in_frame$clock;
    reg  [12:0] pixels$d;
    wire  [12:0] pixels$q;
    reg  pixels$clock;
    reg  [12:0] lines$d;
    wire  [12:0] lines$q;
    reg  lines$clock;
    reg  [12:0] last_pixels$d;
    wire  [12:0] last_pixels$q;
    reg  last_pixels$clock;
    reg  line_short$d;
    wire  line_short$q;
    reg  line_short$clock;
    reg  line_long$d;
    wire  line_long$q;
    reg  line_long$clock;
    reg  frame_short$d;
    wire  frame_short$q;
    reg  frame_short$clock;
    reg  frame_long$d;
    wire  frame_long$q;
    reg  frame_long$clock;
    reg  overflow$d;
    wire  overflow$q;
    reg  overflow$clock;
    reg  skipped$d;
    wire  skipped$q;
    reg  skipped$clock;
    reg  frame_skipped$d;
    wire  frame_skipped$q;
    reg  frame_skipped$clock;
    reg  end_pending$d;
    wire  end_pending$q;
    reg  end_pending$clock;
    reg  [2:0] end_countdown$d;
    wire  [2:0] end_countdown$q;
    reg  end_countdown$clock;
    
    // Local signals
    reg  active;
    reg  fv_rise;
    reg  fv_fall;
    reg  line_end;
    reg  [12:0] width_wide;
    reg  [12:0] height_wide;
    reg  forward;
    reg  first_of_line;
    reg  [12:0] lines_now;
    reg  start_now;
    reg  in_frame_now;
    reg  [12:0] pixels_now;
    reg  [12:0] lines_base;
    reg  [11:0] pixels_reported;
    reg  [11:0] lines_reported;
    reg  [33:0] end_entry;
    
    // Sub module instances
    skylux_core$capture$capture$enable_meta enable_meta(
        .d(enable_meta$d),
        .q(enable_meta$q),
        .clock(enable_meta$clock)
    );
    skylux_core$capture$capture$enable_sync enable_sync(
        .d(enable_sync$d),
        .q(enable_sync$q),
        .clock(enable_sync$clock)
    );
    skylux_core$capture$capture$fv_r fv_r(
        .d(fv_r$d),
        .q(fv_r$q),
        .clock(fv_r$clock)
    );
    skylux_core$capture$capture$lv_r lv_r(
        .d(lv_r$d),
        .q(lv_r$q),
        .clock(lv_r$clock)
    );
    skylux_core$capture$capture$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    skylux_core$capture$capture$prev_fv prev_fv(
        .d(prev_fv$d),
        .q(prev_fv$q),
        .clock(prev_fv$clock)
    );
    skylux_core$capture$capture$prev_active prev_active(
        .d(prev_active$d),
        .q(prev_active$q),
        .clock(prev_active$clock)
    );
    skylux_core$capture$capture$heartbeat_count heartbeat_count(
        .d(heartbeat_count$d),
        .q(heartbeat_count$q),
        .clock(heartbeat_count$clock)
    );
    skylux_core$capture$capture$in_frame in_frame(
        .d(in_frame$d),
        .q(in_frame$q),
        .clock(in_frame$clock)
    );
    skylux_core$capture$capture$pixels pixels(
        .d(pixels$d),
        .q(pixels$q),
        .clock(pixels$clock)
    );
    skylux_core$capture$capture$lines lines(
        .d(lines$d),
        .q(lines$q),
        .clock(lines$clock)
    );
    skylux_core$capture$capture$last_pixels last_pixels(
        .d(last_pixels$d),
        .q(last_pixels$q),
        .clock(last_pixels$clock)
    );
    skylux_core$capture$capture$line_short line_short(
        .d(line_short$d),
        .q(line_short$q),
        .clock(line_short$clock)
    );
    skylux_core$capture$capture$line_long line_long(
        .d(line_long$d),
        .q(line_long$q),
        .clock(line_long$clock)
    );
    skylux_core$capture$capture$frame_short frame_short(
        .d(frame_short$d),
        .q(frame_short$q),
        .clock(frame_short$clock)
    );
    skylux_core$capture$capture$frame_long frame_long(
        .d(frame_long$d),
        .q(frame_long$q),
        .clock(frame_long$clock)
    );
    skylux_core$capture$capture$overflow overflow(
        .d(overflow$d),
        .q(overflow$q),
        .clock(overflow$clock)
    );
    skylux_core$capture$capture$skipped skipped(
        .d(skipped$d),
        .q(skipped$q),
        .clock(skipped$clock)
    );
    skylux_core$capture$capture$frame_skipped frame_skipped(
        .d(frame_skipped$d),
        .q(frame_skipped$q),
        .clock(frame_skipped$clock)
    );
    skylux_core$capture$capture$end_pending end_pending(
        .d(end_pending$d),
        .q(end_pending$q),
        .clock(end_pending$clock)
    );
    skylux_core$capture$capture$end_countdown end_countdown(
        .d(end_countdown$d),
        .q(end_countdown$q),
        .clock(end_countdown$clock)
    );
    
    // Update code
    always @(*) begin
        enable_meta$clock = clock;
        enable_sync$clock = clock;
        fv_r$clock = clock;
        lv_r$clock = clock;
        d_r$clock = clock;
        prev_fv$clock = clock;
        prev_active$clock = clock;
        heartbeat_count$clock = clock;
        in_frame$clock = clock;
        pixels$clock = clock;
        lines$clock = clock;
        last_pixels$clock = clock;
        line_short$clock = clock;
        line_long$clock = clock;
        frame_short$clock = clock;
        frame_long$clock = clock;
        overflow$clock = clock;
        skipped$clock = clock;
        frame_skipped$clock = clock;
        end_pending$clock = clock;
        end_countdown$clock = clock;
        enable_meta$d = enable_meta$q;
        enable_sync$d = enable_sync$q;
        fv_r$d = fv_r$q;
        lv_r$d = lv_r$q;
        d_r$d = d_r$q;
        prev_fv$d = prev_fv$q;
        prev_active$d = prev_active$q;
        heartbeat_count$d = heartbeat_count$q;
        in_frame$d = in_frame$q;
        pixels$d = pixels$q;
        lines$d = lines$q;
        last_pixels$d = last_pixels$q;
        line_short$d = line_short$q;
        line_long$d = line_long$q;
        frame_short$d = frame_short$q;
        frame_long$d = frame_long$q;
        overflow$d = overflow$q;
        skipped$d = skipped$q;
        frame_skipped$d = frame_skipped$q;
        end_pending$d = end_pending$q;
        end_countdown$d = end_countdown$q;
        enable_meta$d = enable;
        enable_sync$d = enable_meta$q;
        fv_r$d = frame_valid;
        lv_r$d = line_valid;
        d_r$d = data;
        prev_fv$d = fv_r$q;
        heartbeat_count$d = heartbeat_count$q + 32'h1;
        heartbeat = heartbeat_count$q[32'h3];
        frame_valid_registered = fv_r$q;
        active = fv_r$q & lv_r$q;
        prev_active$d = active;
        fv_rise = fv_r$q & ~prev_fv$q;
        fv_fall = ~fv_r$q & prev_fv$q & in_frame$q;
        line_end = prev_active$q & ~active & in_frame$q;
        width_wide = ((width) & 13'h1fff);
        height_wide = ((height) & 13'h1fff);
        start_now = 1'b0;
        if (fv_rise & enable_sync$q) begin
            if (~end_pending$q & (fifo_fill < start_limit)) begin
                start_now = 1'b1;
                in_frame$d = 1'b1;
                pixels$d = 32'h0;
                lines$d = 32'h0;
                last_pixels$d = 32'h0;
                line_short$d = 1'b0;
                line_long$d = 1'b0;
                frame_short$d = 1'b0;
                frame_long$d = 1'b0;
                overflow$d = 1'b0;
                frame_skipped$d = skipped$q;
                skipped$d = 1'b0;
            end
            else begin
                skipped$d = 1'b1;
            end
        end
        in_frame_now = in_frame$q | start_now;
        pixels_now = pixels$q;
        lines_base = lines$q;
        if (start_now) begin
            pixels_now = 32'h0;
            lines_base = 32'h0;
        end
        forward = in_frame_now & active & (pixels_now < width_wide) & (lines_base < height_wide);
        first_of_line = ~|pixels_now;
        pixel = d_r$q;
        pixel_valid = forward;
        line_start = forward & first_of_line;
        frame_start = forward & first_of_line & ~|lines_base;
        if (in_frame_now & active & ~&pixels_now) begin
            pixels$d = pixels_now + 32'h1;
        end
        lines_now = lines$q;
        if (line_end) begin
            if (pixels$q < width_wide) begin
                line_short$d = 1'b1;
            end
            if (pixels$q > width_wide) begin
                line_long$d = 1'b1;
            end
            last_pixels$d = pixels$q;
            pixels$d = 32'h0;
            if (~&lines$q) begin
                lines_now = lines$q + 32'h1;
            end
            lines$d = lines_now;
        end
        if (fv_fall) begin
            in_frame$d = 1'b0;
            if (lines_now < height_wide) begin
                frame_short$d = 1'b1;
            end
            if (lines_now > height_wide) begin
                frame_long$d = 1'b1;
            end
            end_pending$d = 1'b1;
            end_countdown$d = end_delay;
        end
        pixels_reported = last_pixels$q[(32'h0)+:(12)];
        if (last_pixels$q[32'hc]) begin
            pixels_reported = 32'hfff;
        end
        lines_reported = lines$q[(32'h0)+:(12)];
        if (lines$q[32'hc]) begin
            lines_reported = 32'hfff;
        end
        if (end_pending$q & |end_countdown$q) begin
            end_countdown$d = end_countdown$q - 32'h1;
        end
        fifo_write = 1'b0;
        fifo_data = 32'h0;
        end_entry = 32'h0;
        if (word_valid) begin
            if (fifo_fill < data_limit) begin
                fifo_write = 1'b1;
                fifo_data = ((word) & 34'h3ffffffff);
            end
            else begin
                overflow$d = 1'b1;
            end
        end
        else if (end_pending$q & ~|end_countdown$q) begin
            end_entry = end_marker | ((pixels_reported) & 34'h3ffffffff) | (((lines_reported) & 34'h3ffffffff) << 32'hc);
            end_entry = (end_entry & ~(1 << (32'h18)) | ((line_short$q) << (32'h18)));
            end_entry = (end_entry & ~(1 << (32'h19)) | ((line_long$q) << (32'h19)));
            end_entry = (end_entry & ~(1 << (32'h1a)) | ((frame_short$q) << (32'h1a)));
            end_entry = (end_entry & ~(1 << (32'h1b)) | ((frame_long$q) << (32'h1b)));
            end_entry = (end_entry & ~(1 << (32'h1c)) | ((overflow$q) << (32'h1c)));
            end_entry = (end_entry & ~(1 << (32'h1d)) | ((frame_skipped$q) << (32'h1d)));
            fifo_write = 1'b1;
            fifo_data = end_entry;
            end_pending$d = 1'b0;
        end
        else if (start_now) begin
            fifo_write = 1'b1;
            fifo_data = start_marker;
        end
    end
    
endmodule // skylux_core$capture$capture


module skylux_core$capture$capture$d_r(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$capture$d_r


module skylux_core$capture$capture$enable_meta(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$capture$enable_meta


module skylux_core$capture$capture$enable_sync(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$capture$enable_sync


module skylux_core$capture$capture$end_countdown(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$capture$end_countdown


module skylux_core$capture$capture$end_pending(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$capture$end_pending


module skylux_core$capture$capture$frame_long(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$capture$frame_long


module skylux_core$capture$capture$frame_short(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$capture$frame_short


module skylux_core$capture$capture$frame_skipped(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$capture$frame_skipped


module skylux_core$capture$capture$fv_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$capture$fv_r


module skylux_core$capture$capture$heartbeat_count(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$capture$heartbeat_count


module skylux_core$capture$capture$in_frame(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$capture$in_frame


module skylux_core$capture$capture$last_pixels(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$capture$last_pixels


module skylux_core$capture$capture$line_long(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$capture$line_long


module skylux_core$capture$capture$line_short(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$capture$line_short


module skylux_core$capture$capture$lines(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$capture$lines


module skylux_core$capture$capture$lv_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$capture$lv_r


module skylux_core$capture$capture$overflow(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$capture$overflow


module skylux_core$capture$capture$pixels(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$capture$pixels


module skylux_core$capture$capture$prev_active(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$capture$prev_active


module skylux_core$capture$capture$prev_fv(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$capture$prev_fv


module skylux_core$capture$capture$skipped(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$capture$skipped


module skylux_core$capture$fifo(read,data_out,empty,almost_empty,underflow,read_clock,read_fill,write,data_in,full,almost_full,overflow,write_clock,write_fill);
    
    // Module arguments
    input wire  read;
    output reg  [33:0] data_out;
    output reg  empty;
    output reg  almost_empty;
    output reg  underflow;
    input wire  read_clock;
    output reg  [7:0] read_fill;
    input wire  write;
    input wire  [33:0] data_in;
    output reg  full;
    output reg  almost_full;
    output reg  overflow;
    input wire  write_clock;
    output reg  [7:0] write_fill;
    
    // Stub signals
    reg  [6:0] ram$read_address;
    reg  ram$read_clock;
    wire  [33:0] ram$read_data;
    reg  [6:0] ram$write_address;
    reg  ram$write_clock;
    reg  [33:0] ram$write_data;
    reg  ram$write_enable;
    reg  read_logic$clock;
    reg  read_logic$read;
    wire  [33:0] read_logic$data_out;
    wire  read_logic$empty;
    wire  read_logic$almost_empty;
    wire  read_logic$underflow;
    reg  [7:0] read_logic$write_address_delayed;
    wire  [6:0] read_logic$ram_read_address;
    reg  [33:0] read_logic$ram_read_data;
    wire  read_logic$ram_read_clock;
    wire  [7:0] read_logic$read_address_out;
    wire  [7:0] read_logic$fill_level;
    reg  write_logic$write;
    reg  [33:0] write_logic$data_in;
    wire  write_logic$full;
    wire  write_logic$almost_full;
    wire  write_logic$overflow;
    reg  write_logic$clock;
    wire  [6:0] write_logic$ram_write_address;
    wire  write_logic$ram_write_clock;
    wire  [33:0] write_logic$ram_write_data;
    wire  write_logic$ram_write_enable;
    reg  [7:0] write_logic$read_address;
    wire  [7:0] write_logic$write_address_delayed;
    wire  [7:0] write_logic$fill_level;
    reg  write_to_read$clock_in;
    reg  [7:0] write_to_read$sig_in;
    wire  write_to_read$busy;
    reg  write_to_read$send;
    reg  write_to_read$clock_out;
    wire  [7:0] write_to_read$sig_out;
    wire  write_to_read$update;
    reg  read_to_write$clock_in;
    reg  [7:0] read_to_write$sig_in;
    wire  read_to_write$busy;
    reg  read_to_write$send;
    reg  read_to_write$clock_out;
    wire  [7:0] read_to_write$sig_out;
    wire  read_to_write$update;
    
    // Sub module instances
    skylux_core$capture$fifo$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    skylux_core$capture$fifo$read_logic read_logic(
        .clock(read_logic$clock),
        .read(read_logic$read),
        .data_out(read_logic$data_out),
        .empty(read_logic$empty),
        .almost_empty(read_logic$almost_empty),
        .underflow(read_logic$underflow),
        .write_address_delayed(read_logic$write_address_delayed),
        .ram_read_address(read_logic$ram_read_address),
        .ram_read_data(read_logic$ram_read_data),
        .ram_read_clock(read_logic$ram_read_clock),
        .read_address_out(read_logic$read_address_out),
        .fill_level(read_logic$fill_level)
    );
    skylux_core$capture$fifo$write_logic write_logic(
        .write(write_logic$write),
        .data_in(write_logic$data_in),
        .full(write_logic$full),
        .almost_full(write_logic$almost_full),
        .overflow(write_logic$overflow),
        .clock(write_logic$clock),
        .ram_write_address(write_logic$ram_write_address),
        .ram_write_clock(write_logic$ram_write_clock),
        .ram_write_data(write_logic$ram_write_data),
        .ram_write_enable(write_logic$ram_write_enable),
        .read_address(write_logic$read_address),
        .write_address_delayed(write_logic$write_address_delayed),
        .fill_level(write_logic$fill_level)
    );
    skylux_core$capture$fifo$write_to_read write_to_read(
        .clock_in(write_to_read$clock_in),
        .sig_in(write_to_read$sig_in),
        .busy(write_to_read$busy),
        .send(write_to_read$send),
        .clock_out(write_to_read$clock_out),
        .sig_out(write_to_read$sig_out),
        .update(write_to_read$update)
    );
    skylux_core$capture$fifo$read_to_write read_to_write(
        .clock_in(read_to_write$clock_in),
        .sig_in(read_to_write$sig_in),
        .busy(read_to_write$busy),
        .send(read_to_write$send),
        .clock_out(read_to_write$clock_out),
        .sig_out(read_to_write$sig_out),
        .update(read_to_write$update)
    );
    
    // Update code
    always @(*) begin
        read_logic$clock = read_clock;
        read_logic$read = read;
        empty = read_logic$empty;
        almost_empty = read_logic$almost_empty;
        data_out = read_logic$data_out;
        underflow = read_logic$underflow;
        write_logic$clock = write_clock;
        overflow = write_logic$overflow;
        almost_full = write_logic$almost_full;
        full = write_logic$full;
        write_logic$write = write;
        write_logic$data_in = data_in;
        ram$write_clock = write_logic$ram_write_clock;
        ram$write_enable = write_logic$ram_write_enable;
        ram$write_address = write_logic$ram_write_address;
        ram$write_data = write_logic$ram_write_data;
        ram$read_clock = read_logic$ram_read_clock;
        ram$read_address = read_logic$ram_read_address;
        read_logic$ram_read_data = ram$read_data;
        read_to_write$clock_in = read_clock;
        read_to_write$clock_out = write_clock;
        read_to_write$sig_in = read_logic$read_address_out;
        write_logic$read_address = read_to_write$sig_out;
        read_to_write$send = ~read_to_write$busy;
        write_to_read$clock_in = write_clock;
        write_to_read$clock_out = read_clock;
        write_to_read$sig_in = write_logic$write_address_delayed;
        read_logic$write_address_delayed = write_to_read$sig_out;
        write_to_read$send = ~write_to_read$busy;
        write_fill = write_logic$fill_level;
        read_fill = read_logic$fill_level;
    end
    
endmodule // skylux_core$capture$fifo


module skylux_core$capture$fifo$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [6:0] read_address;
    input wire  read_clock;
    output reg  [33:0] read_data;
    input wire  [6:0] write_address;
    input wire  write_clock;
    input wire  [33:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[33:0] mem[127:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // skylux_core$capture$fifo$ram


module skylux_core$capture$fifo$read_logic(clock,read,data_out,empty,almost_empty,underflow,write_address_delayed,ram_read_address,ram_read_data,ram_read_clock,read_address_out,fill_level);
    
    // Module arguments
    input wire  clock;
    input wire  read;
    output reg  [33:0] data_out;
    output reg  empty;
    output reg  almost_empty;
    output reg  underflow;
    input wire  [7:0] write_address_delayed;
    output reg  [6:0] ram_read_address;
    input wire  [33:0] ram_read_data;
    output reg  ram_read_clock;
    output reg  [7:0] read_address_out;
    output reg  [7:0] fill_level;
    
    // Constant declarations
    localparam  fifo_address_mask = 8'h7f;
    localparam  fifo_size = 8'h80;
    localparam  block_size = 8'h1;
    
    // Stub signals
    reg  [7:0] read_address$d;
    wire  [7:0] read_address$q;
    reg  read_address$clock;
    reg  dff_underflow$d;
    wire  dff_underflow$q;
    reg  dff_underflow$clock;
    
    // Local signals
    reg  is_empty;
    reg  is_full;
    
    // Sub module instances
    skylux_core$capture$fifo$read_logic$read_address read_address(
        .d(read_address$d),
        .q(read_address$q),
        .clock(read_address$clock)
    );
    skylux_core$capture$fifo$read_logic$dff_underflow dff_underflow(
        .d(dff_underflow$d),
        .q(dff_underflow$q),
        .clock(dff_underflow$clock)
    );
    
    // Update code
    always @(*) begin
        read_address$clock = clock;
        dff_underflow$clock = clock;
        read_address$d = read_address$q;
        dff_underflow$d = dff_underflow$q;
        ram_read_clock = clock;
        is_empty = (read_address$q == write_address_delayed);
        is_full = ~is_empty & ((read_address$q & fifo_address_mask) == (write_address_delayed & fifo_address_mask));
        fill_level = ((write_address_delayed & fifo_address_mask) + fifo_size - (read_address$q & fifo_address_mask)) & fifo_address_mask;
        if (is_full) begin
            fill_level = fifo_size;
        end
        almost_empty = (fill_level < block_size);
        empty = is_empty;
        ram_read_address = ((read_address$q & fifo_address_mask) & 7'h7f);
        data_out = ram_read_data;
        if (read & ~is_empty) begin
            read_address$d = read_address$q + 32'h1;
            ram_read_address = (((read_address$q + 32'h1) & fifo_address_mask) & 7'h7f);
        end
        else begin
            read_address$d = read_address$q;
        end
        dff_underflow$d = dff_underflow$q | (is_empty & read);
        underflow = dff_underflow$q;
        read_address_out = read_address$q;
    end
    
endmodule // skylux_core$capture$fifo$read_logic


module skylux_core$capture$fifo$read_logic$dff_underflow(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$fifo$read_logic$dff_underflow


module skylux_core$capture$fifo$read_logic$read_address(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$fifo$read_logic$read_address


module skylux_core$capture$fifo$read_to_write(clock_in,sig_in,busy,send,clock_out,sig_out,update);
    
    // Module arguments
    input wire  clock_in;
    input wire  [7:0] sig_in;
    output reg  busy;
    input wire  send;
    input wire  clock_out;
    output reg  [7:0] sig_out;
    output reg  update;
    
    // Stub signals
    reg  [7:0] sender$sig_in;
    reg  sender$clock;
    wire  [7:0] sender$sig_cross;
    wire  sender$flag_out;
    reg  sender$ack_in;
    wire  sender$busy;
    reg  sender$send;
    wire  [7:0] recv$sig_out;
    reg  recv$clock;
    reg  [7:0] recv$sig_cross;
    reg  recv$flag_in;
    wire  recv$ack_out;
    wire  recv$update;
    
    // Sub module instances
    skylux_core$capture$fifo$read_to_write$sender sender(
        .sig_in(sender$sig_in),
        .clock(sender$clock),
        .sig_cross(sender$sig_cross),
        .flag_out(sender$flag_out),
        .ack_in(sender$ack_in),
        .busy(sender$busy),
        .send(sender$send)
    );
    skylux_core$capture$fifo$read_to_write$recv recv(
        .sig_out(recv$sig_out),
        .clock(recv$clock),
        .sig_cross(recv$sig_cross),
        .flag_in(recv$flag_in),
        .ack_out(recv$ack_out),
        .update(recv$update)
    );
    
    // Update code
    always @(*) begin
        sender$clock = clock_in;
        recv$clock = clock_out;
        sender$sig_in = sig_in;
        busy = sender$busy;
        sender$send = send;
        sig_out = recv$sig_out;
        update = recv$update;
        recv$sig_cross = sender$sig_cross;
        recv$flag_in = sender$flag_out;
        sender$ack_in = recv$ack_out;
    end
    
endmodule // skylux_core$capture$fifo$read_to_write


module skylux_core$capture$fifo$read_to_write$recv(sig_out,clock,sig_cross,flag_in,ack_out,update);
    
    // Module arguments
    output reg  [7:0] sig_out;
    input wire  clock;
    input wire  [7:0] sig_cross;
    input wire  flag_in;
    output reg  ack_out;
    output reg  update;
    
    // Enums
    localparam SyncReceiverState$WaitSteady = 0;
    localparam SyncReceiverState$WaitDone = 1;
    
    // Stub signals
    reg  [7:0] hold$d;
    wire  [7:0] hold$q;
    reg  hold$clock;
    reg  update_delay$d;
    wire  update_delay$q;
    reg  update_delay$clock;
    reg  state$d;
    wire  state$q;
    reg  state$clock;
    reg  sync$sig_in;
    wire  sync$sig_out;
    reg  sync$clock;
    
    // Sub module instances
    skylux_core$capture$fifo$read_to_write$recv$hold hold(
        .d(hold$d),
        .q(hold$q),
        .clock(hold$clock)
    );
    skylux_core$capture$fifo$read_to_write$recv$update_delay update_delay(
        .d(update_delay$d),
        .q(update_delay$q),
        .clock(update_delay$clock)
    );
    skylux_core$capture$fifo$read_to_write$recv$state state(
        .d(state$d),
        .q(state$q),
        .clock(state$clock)
    );
    skylux_core$capture$fifo$read_to_write$recv$sync sync(
        .sig_in(sync$sig_in),
        .sig_out(sync$sig_out),
        .clock(sync$clock)
    );
    
    // Update code
    always @(*) begin
        hold$clock = clock;
        update_delay$clock = clock;
        state$clock = clock;
        hold$d = hold$q;
        update_delay$d = update_delay$q;
        state$d = state$q;
        sync$clock = clock;
        sig_out = hold$q;
        ack_out = 1'b0;
        sync$sig_in = flag_in;
        update = update_delay$q;
        update_delay$d = 1'b0;
        case (state$q)
            SyncReceiverState$WaitSteady:
                begin
                    if (sync$sig_out) begin
                        ack_out = 1'b1;
                        state$d = SyncReceiverState$WaitDone;
                    end
                end
            SyncReceiverState$WaitDone:
                begin
                    if (~sync$sig_out) begin
                        ack_out = 1'b0;
                        update_delay$d = 1'b1;
                        hold$d = sig_cross;
                        state$d = SyncReceiverState$WaitSteady;
                    end
                    else begin
                        ack_out = 1'b1;
                    end
                end
            default:
                begin
                    state$d = SyncReceiverState$WaitSteady;
                end
        endcase
    end
    
endmodule // skylux_core$capture$fifo$read_to_write$recv


module skylux_core$capture$fifo$read_to_write$recv$hold(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$fifo$read_to_write$recv$hold


module skylux_core$capture$fifo$read_to_write$recv$state(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Enums
    localparam SyncReceiverState$WaitSteady = 0;
    localparam SyncReceiverState$WaitDone = 1;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$fifo$read_to_write$recv$state


module skylux_core$capture$fifo$read_to_write$recv$sync(sig_in,sig_out,clock);
    
    // Module arguments
    input wire  sig_in;
    output reg  sig_out;
    input wire  clock;
    
    // Stub signals
    reg  dff0$d;
    wire  dff0$q;
    reg  dff0$clock;
    reg  dff1$d;
    wire  dff1$q;
    reg  dff1$clock;
    
    // Sub module instances
    skylux_core$capture$fifo$read_to_write$recv$sync$dff0 dff0(
        .d(dff0$d),
        .q(dff0$q),
        .clock(dff0$clock)
    );
    skylux_core$capture$fifo$read_to_write$recv$sync$dff1 dff1(
        .d(dff1$d),
        .q(dff1$q),
        .clock(dff1$clock)
    );
    
    // Update code
    always @(*) begin
        dff0$clock = clock;
        dff1$clock = clock;
        dff0$d = dff0$q;
        dff1$d = dff1$q;
        dff0$d = sig_in;
        dff1$d = dff0$q;
        sig_out = dff1$q;
    end
    
endmodule // skylux_core$capture$fifo$read_to_write$recv$sync


module skylux_core$capture$fifo$read_to_write$recv$sync$dff0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$fifo$read_to_write$recv$sync$dff0


module skylux_core$capture$fifo$read_to_write$recv$sync$dff1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$fifo$read_to_write$recv$sync$dff1


module skylux_core$capture$fifo$read_to_write$recv$update_delay(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$fifo$read_to_write$recv$update_delay


module skylux_core$capture$fifo$read_to_write$sender(sig_in,clock,sig_cross,flag_out,ack_in,busy,send);
    
    // Module arguments
    input wire  [7:0] sig_in;
    input wire  clock;
    output reg  [7:0] sig_cross;
    output reg  flag_out;
    input wire  ack_in;
    output reg  busy;
    input wire  send;
    
    // Enums
    localparam SyncSenderState$Idle = 0;
    localparam SyncSenderState$WaitAck = 1;
    localparam SyncSenderState$WaitDone = 2;
    
    // Stub signals
    reg  [7:0] hold$d;
    wire  [7:0] hold$q;
    reg  hold$clock;
    reg  [1:0] state$d;
    wire  [1:0] state$q;
    reg  state$clock;
    reg  sync$sig_in;
    wire  sync$sig_out;
    reg  sync$clock;
    
    // Sub module instances
    skylux_core$capture$fifo$read_to_write$sender$hold hold(
        .d(hold$d),
        .q(hold$q),
        .clock(hold$clock)
    );
    skylux_core$capture$fifo$read_to_write$sender$state state(
        .d(state$d),
        .q(state$q),
        .clock(state$clock)
    );
    skylux_core$capture$fifo$read_to_write$sender$sync sync(
        .sig_in(sync$sig_in),
        .sig_out(sync$sig_out),
        .clock(sync$clock)
    );
    
    // Update code
    always @(*) begin
        hold$clock = clock;
        state$clock = clock;
        hold$d = hold$q;
        state$d = state$q;
        sync$clock = clock;
        sig_cross = hold$q;
        flag_out = 1'b0;
        sync$sig_in = ack_in;
        busy = 1'b1;
        case (state$q)
            SyncSenderState$Idle:
                begin
                    busy = 1'b0;
                    if (send) begin
                        hold$d = sig_in;
                        state$d = SyncSenderState$WaitAck;
                        flag_out = 1'b1;
                    end
                end
            SyncSenderState$WaitAck:
                begin
                    flag_out = 1'b1;
                    if (sync$sig_out) begin
                        state$d = SyncSenderState$WaitDone;
                        flag_out = 1'b0;
                    end
                end
            SyncSenderState$WaitDone:
                begin
                    if (~sync$sig_out) begin
                        hold$d = sig_in;
                        flag_out = 1'b1;
                        state$d = SyncSenderState$Idle;
                    end
                end
            default:
                begin
                    state$d = SyncSenderState$Idle;
                end
        endcase
    end
    
endmodule // skylux_core$capture$fifo$read_to_write$sender


module skylux_core$capture$fifo$read_to_write$sender$hold(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$fifo$read_to_write$sender$hold


module skylux_core$capture$fifo$read_to_write$sender$state(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Enums
    localparam SyncSenderState$Idle = 0;
    localparam SyncSenderState$WaitAck = 1;
    localparam SyncSenderState$WaitDone = 2;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$fifo$read_to_write$sender$state


module skylux_core$capture$fifo$read_to_write$sender$sync(sig_in,sig_out,clock);
    
    // Module arguments
    input wire  sig_in;
    output reg  sig_out;
    input wire  clock;
    
    // Stub signals
    reg  dff0$d;
    wire  dff0$q;
    reg  dff0$clock;
    reg  dff1$d;
    wire  dff1$q;
    reg  dff1$clock;
    
    // Sub module instances
    skylux_core$capture$fifo$read_to_write$sender$sync$dff0 dff0(
        .d(dff0$d),
        .q(dff0$q),
        .clock(dff0$clock)
    );
    skylux_core$capture$fifo$read_to_write$sender$sync$dff1 dff1(
        .d(dff1$d),
        .q(dff1$q),
        .clock(dff1$clock)
    );
    
    // Update code
    always @(*) begin
        dff0$clock = clock;
        dff1$clock = clock;
        dff0$d = dff0$q;
        dff1$d = dff1$q;
        dff0$d = sig_in;
        dff1$d = dff0$q;
        sig_out = dff1$q;
    end
    
endmodule // skylux_core$capture$fifo$read_to_write$sender$sync


module skylux_core$capture$fifo$read_to_write$sender$sync$dff0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$fifo$read_to_write$sender$sync$dff0


module skylux_core$capture$fifo$read_to_write$sender$sync$dff1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$fifo$read_to_write$sender$sync$dff1


module skylux_core$capture$fifo$write_logic(write,data_in,full,almost_full,overflow,clock,ram_write_address,ram_write_clock,ram_write_data,ram_write_enable,read_address,write_address_delayed,fill_level);
    
    // Module arguments
    input wire  write;
    input wire  [33:0] data_in;
    output reg  full;
    output reg  almost_full;
    output reg  overflow;
    input wire  clock;
    output reg  [6:0] ram_write_address;
    output reg  ram_write_clock;
    output reg  [33:0] ram_write_data;
    output reg  ram_write_enable;
    input wire  [7:0] read_address;
    output reg  [7:0] write_address_delayed;
    output reg  [7:0] fill_level;
    
    // Constant declarations
    localparam  fifo_address_mask = 8'h7f;
    localparam  fifo_size = 8'h80;
    localparam  almost_full_level = 8'h7f;
    
    // Stub signals
    reg  [7:0] write_address$d;
    wire  [7:0] write_address$q;
    reg  write_address$clock;
    reg  [7:0] dff_write_address_delay$d;
    wire  [7:0] dff_write_address_delay$q;
    reg  dff_write_address_delay$clock;
    reg  dff_overflow$d;
    wire  dff_overflow$q;
    reg  dff_overflow$clock;
    
    // Local signals
    reg  is_empty;
    reg  is_full;
    
    // Sub module instances
    skylux_core$capture$fifo$write_logic$write_address write_address(
        .d(write_address$d),
        .q(write_address$q),
        .clock(write_address$clock)
    );
    skylux_core$capture$fifo$write_logic$dff_write_address_delay dff_write_address_delay(
        .d(dff_write_address_delay$d),
        .q(dff_write_address_delay$q),
        .clock(dff_write_address_delay$clock)
    );
    skylux_core$capture$fifo$write_logic$dff_overflow dff_overflow(
        .d(dff_overflow$d),
        .q(dff_overflow$q),
        .clock(dff_overflow$clock)
    );
    
    // Update code
    always @(*) begin
        dff_overflow$clock = clock;
        write_address$clock = clock;
        dff_write_address_delay$clock = clock;
        dff_overflow$d = dff_overflow$q;
        write_address$d = write_address$q;
        dff_write_address_delay$d = dff_write_address_delay$q;
        ram_write_clock = clock;
        dff_write_address_delay$d = write_address$q;
        write_address_delayed = dff_write_address_delay$q;
        ram_write_enable = 1'b0;
        is_empty = (read_address == dff_write_address_delay$q);
        is_full = ~is_empty & ((read_address & fifo_address_mask) == (write_address$q & fifo_address_mask));
        fill_level = ((dff_write_address_delay$q & fifo_address_mask) + fifo_size - (read_address & fifo_address_mask)) & fifo_address_mask;
        if (is_full) begin
            fill_level = fifo_size;
        end
        almost_full = (fill_level >= almost_full_level);
        full = is_full;
        ram_write_address = ((write_address$q & fifo_address_mask) & 7'h7f);
        ram_write_data = data_in;
        if (write & ~is_full) begin
            write_address$d = write_address$q + 32'h1;
            ram_write_enable = 1'b1;
        end
        else begin
            write_address$d = write_address$q;
            ram_write_enable = 1'b0;
        end
        dff_overflow$d = dff_overflow$q | (is_full & write);
        overflow = dff_overflow$q;
    end
    
endmodule // skylux_core$capture$fifo$write_logic


module skylux_core$capture$fifo$write_logic$dff_overflow(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$fifo$write_logic$dff_overflow


module skylux_core$capture$fifo$write_logic$dff_write_address_delay(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$fifo$write_logic$dff_write_address_delay


module skylux_core$capture$fifo$write_logic$write_address(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$fifo$write_logic$write_address


module skylux_core$capture$fifo$write_to_read(clock_in,sig_in,busy,send,clock_out,sig_out,update);
    
    // Module arguments
    input wire  clock_in;
    input wire  [7:0] sig_in;
    output reg  busy;
    input wire  send;
    input wire  clock_out;
    output reg  [7:0] sig_out;
    output reg  update;
    
    // Stub signals
    reg  [7:0] sender$sig_in;
    reg  sender$clock;
    wire  [7:0] sender$sig_cross;
    wire  sender$flag_out;
    reg  sender$ack_in;
    wire  sender$busy;
    reg  sender$send;
    wire  [7:0] recv$sig_out;
    reg  recv$clock;
    reg  [7:0] recv$sig_cross;
    reg  recv$flag_in;
    wire  recv$ack_out;
    wire  recv$update;
    
    // Sub module instances
    skylux_core$capture$fifo$write_to_read$sender sender(
        .sig_in(sender$sig_in),
        .clock(sender$clock),
        .sig_cross(sender$sig_cross),
        .flag_out(sender$flag_out),
        .ack_in(sender$ack_in),
        .busy(sender$busy),
        .send(sender$send)
    );
    skylux_core$capture$fifo$write_to_read$recv recv(
        .sig_out(recv$sig_out),
        .clock(recv$clock),
        .sig_cross(recv$sig_cross),
        .flag_in(recv$flag_in),
        .ack_out(recv$ack_out),
        .update(recv$update)
    );
    
    // Update code
    always @(*) begin
        sender$clock = clock_in;
        recv$clock = clock_out;
        sender$sig_in = sig_in;
        busy = sender$busy;
        sender$send = send;
        sig_out = recv$sig_out;
        update = recv$update;
        recv$sig_cross = sender$sig_cross;
        recv$flag_in = sender$flag_out;
        sender$ack_in = recv$ack_out;
    end
    
endmodule // skylux_core$capture$fifo$write_to_read


module skylux_core$capture$fifo$write_to_read$recv(sig_out,clock,sig_cross,flag_in,ack_out,update);
    
    // Module arguments
    output reg  [7:0] sig_out;
    input wire  clock;
    input wire  [7:0] sig_cross;
    input wire  flag_in;
    output reg  ack_out;
    output reg  update;
    
    // Enums
    localparam SyncReceiverState$WaitSteady = 0;
    localparam SyncReceiverState$WaitDone = 1;
    
    // Stub signals
    reg  [7:0] hold$d;
    wire  [7:0] hold$q;
    reg  hold$clock;
    reg  update_delay$d;
    wire  update_delay$q;
    reg  update_delay$clock;
    reg  state$d;
    wire  state$q;
    reg  state$clock;
    reg  sync$sig_in;
    wire  sync$sig_out;
    reg  sync$clock;
    
    // Sub module instances
    skylux_core$capture$fifo$write_to_read$recv$hold hold(
        .d(hold$d),
        .q(hold$q),
        .clock(hold$clock)
    );
    skylux_core$capture$fifo$write_to_read$recv$update_delay update_delay(
        .d(update_delay$d),
        .q(update_delay$q),
        .clock(update_delay$clock)
    );
    skylux_core$capture$fifo$write_to_read$recv$state state(
        .d(state$d),
        .q(state$q),
        .clock(state$clock)
    );
    skylux_core$capture$fifo$write_to_read$recv$sync sync(
        .sig_in(sync$sig_in),
        .sig_out(sync$sig_out),
        .clock(sync$clock)
    );
    
    // Update code
    always @(*) begin
        hold$clock = clock;
        update_delay$clock = clock;
        state$clock = clock;
        hold$d = hold$q;
        update_delay$d = update_delay$q;
        state$d = state$q;
        sync$clock = clock;
        sig_out = hold$q;
        ack_out = 1'b0;
        sync$sig_in = flag_in;
        update = update_delay$q;
        update_delay$d = 1'b0;
        case (state$q)
            SyncReceiverState$WaitSteady:
                begin
                    if (sync$sig_out) begin
                        ack_out = 1'b1;
                        state$d = SyncReceiverState$WaitDone;
                    end
                end
            SyncReceiverState$WaitDone:
                begin
                    if (~sync$sig_out) begin
                        ack_out = 1'b0;
                        update_delay$d = 1'b1;
                        hold$d = sig_cross;
                        state$d = SyncReceiverState$WaitSteady;
                    end
                    else begin
                        ack_out = 1'b1;
                    end
                end
            default:
                begin
                    state$d = SyncReceiverState$WaitSteady;
                end
        endcase
    end
    
endmodule // skylux_core$capture$fifo$write_to_read$recv


module skylux_core$capture$fifo$write_to_read$recv$hold(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$fifo$write_to_read$recv$hold


module skylux_core$capture$fifo$write_to_read$recv$state(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Enums
    localparam SyncReceiverState$WaitSteady = 0;
    localparam SyncReceiverState$WaitDone = 1;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$fifo$write_to_read$recv$state


module skylux_core$capture$fifo$write_to_read$recv$sync(sig_in,sig_out,clock);
    
    // Module arguments
    input wire  sig_in;
    output reg  sig_out;
    input wire  clock;
    
    // Stub signals
    reg  dff0$d;
    wire  dff0$q;
    reg  dff0$clock;
    reg  dff1$d;
    wire  dff1$q;
    reg  dff1$clock;
    
    // Sub module instances
    skylux_core$capture$fifo$write_to_read$recv$sync$dff0 dff0(
        .d(dff0$d),
        .q(dff0$q),
        .clock(dff0$clock)
    );
    skylux_core$capture$fifo$write_to_read$recv$sync$dff1 dff1(
        .d(dff1$d),
        .q(dff1$q),
        .clock(dff1$clock)
    );
    
    // Update code
    always @(*) begin
        dff0$clock = clock;
        dff1$clock = clock;
        dff0$d = dff0$q;
        dff1$d = dff1$q;
        dff0$d = sig_in;
        dff1$d = dff0$q;
        sig_out = dff1$q;
    end
    
endmodule // skylux_core$capture$fifo$write_to_read$recv$sync


module skylux_core$capture$fifo$write_to_read$recv$sync$dff0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$fifo$write_to_read$recv$sync$dff0


module skylux_core$capture$fifo$write_to_read$recv$sync$dff1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$fifo$write_to_read$recv$sync$dff1


module skylux_core$capture$fifo$write_to_read$recv$update_delay(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$fifo$write_to_read$recv$update_delay


module skylux_core$capture$fifo$write_to_read$sender(sig_in,clock,sig_cross,flag_out,ack_in,busy,send);
    
    // Module arguments
    input wire  [7:0] sig_in;
    input wire  clock;
    output reg  [7:0] sig_cross;
    output reg  flag_out;
    input wire  ack_in;
    output reg  busy;
    input wire  send;
    
    // Enums
    localparam SyncSenderState$Idle = 0;
    localparam SyncSenderState$WaitAck = 1;
    localparam SyncSenderState$WaitDone = 2;
    
    // Stub signals
    reg  [7:0] hold$d;
    wire  [7:0] hold$q;
    reg  hold$clock;
    reg  [1:0] state$d;
    wire  [1:0] state$q;
    reg  state$clock;
    reg  sync$sig_in;
    wire  sync$sig_out;
    reg  sync$clock;
    
    // Sub module instances
    skylux_core$capture$fifo$write_to_read$sender$hold hold(
        .d(hold$d),
        .q(hold$q),
        .clock(hold$clock)
    );
    skylux_core$capture$fifo$write_to_read$sender$state state(
        .d(state$d),
        .q(state$q),
        .clock(state$clock)
    );
    skylux_core$capture$fifo$write_to_read$sender$sync sync(
        .sig_in(sync$sig_in),
        .sig_out(sync$sig_out),
        .clock(sync$clock)
    );
    
    // Update code
    always @(*) begin
        hold$clock = clock;
        state$clock = clock;
        hold$d = hold$q;
        state$d = state$q;
        sync$clock = clock;
        sig_cross = hold$q;
        flag_out = 1'b0;
        sync$sig_in = ack_in;
        busy = 1'b1;
        case (state$q)
            SyncSenderState$Idle:
                begin
                    busy = 1'b0;
                    if (send) begin
                        hold$d = sig_in;
                        state$d = SyncSenderState$WaitAck;
                        flag_out = 1'b1;
                    end
                end
            SyncSenderState$WaitAck:
                begin
                    flag_out = 1'b1;
                    if (sync$sig_out) begin
                        state$d = SyncSenderState$WaitDone;
                        flag_out = 1'b0;
                    end
                end
            SyncSenderState$WaitDone:
                begin
                    if (~sync$sig_out) begin
                        hold$d = sig_in;
                        flag_out = 1'b1;
                        state$d = SyncSenderState$Idle;
                    end
                end
            default:
                begin
                    state$d = SyncSenderState$Idle;
                end
        endcase
    end
    
endmodule // skylux_core$capture$fifo$write_to_read$sender


module skylux_core$capture$fifo$write_to_read$sender$hold(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$fifo$write_to_read$sender$hold


module skylux_core$capture$fifo$write_to_read$sender$state(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Enums
    localparam SyncSenderState$Idle = 0;
    localparam SyncSenderState$WaitAck = 1;
    localparam SyncSenderState$WaitDone = 2;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$fifo$write_to_read$sender$state


module skylux_core$capture$fifo$write_to_read$sender$sync(sig_in,sig_out,clock);
    
    // Module arguments
    input wire  sig_in;
    output reg  sig_out;
    input wire  clock;
    
    // Stub signals
    reg  dff0$d;
    wire  dff0$q;
    reg  dff0$clock;
    reg  dff1$d;
    wire  dff1$q;
    reg  dff1$clock;
    
    // Sub module instances
    skylux_core$capture$fifo$write_to_read$sender$sync$dff0 dff0(
        .d(dff0$d),
        .q(dff0$q),
        .clock(dff0$clock)
    );
    skylux_core$capture$fifo$write_to_read$sender$sync$dff1 dff1(
        .d(dff1$d),
        .q(dff1$q),
        .clock(dff1$clock)
    );
    
    // Update code
    always @(*) begin
        dff0$clock = clock;
        dff1$clock = clock;
        dff0$d = dff0$q;
        dff1$d = dff1$q;
        dff0$d = sig_in;
        dff1$d = dff0$q;
        sig_out = dff1$q;
    end
    
endmodule // skylux_core$capture$fifo$write_to_read$sender$sync


module skylux_core$capture$fifo$write_to_read$sender$sync$dff0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$fifo$write_to_read$sender$sync$dff0


module skylux_core$capture$fifo$write_to_read$sender$sync$dff1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$fifo$write_to_read$sender$sync$dff1


module skylux_core$capture$grouper(clock,pixel,pixel_valid,line_start,frame_start,phase,black,valid_min,valid_max,weight_r,weight_g,weight_b,raw,word,word_valid);
    
    // Module arguments
    input wire  clock;
    input wire  [11:0] pixel;
    input wire  pixel_valid;
    input wire  line_start;
    input wire  frame_start;
    input wire  [1:0] phase;
    input wire  [11:0] black;
    input wire  [11:0] valid_min;
    input wire  [11:0] valid_max;
    input wire  [15:0] weight_r;
    input wire  [15:0] weight_g;
    input wire  [15:0] weight_b;
    input wire  raw;
    output reg  [31:0] word;
    output reg  word_valid;
    
    // Stub signals
    reg  quads$clock;
    reg  [11:0] quads$pixel;
    reg  quads$pixel_valid;
    reg  quads$line_start;
    reg  quads$frame_start;
    reg  quads$raw;
    wire  quads$quad_valid;
    wire  quads$pair_valid;
    wire  [11:0] quads$top_left;
    wire  [11:0] quads$top_right;
    wire  [11:0] quads$bottom_left;
    wire  [11:0] quads$bottom_right;
    reg  luma$clock;
    reg  luma$quad_valid;
    reg  [11:0] luma$top_left;
    reg  [11:0] luma$top_right;
    reg  [11:0] luma$bottom_left;
    reg  [11:0] luma$bottom_right;
    reg  [1:0] luma$phase;
    reg  [11:0] luma$black;
    reg  [11:0] luma$valid_min;
    reg  [11:0] luma$valid_max;
    reg  [15:0] luma$weight_r;
    reg  [15:0] luma$weight_g;
    reg  [15:0] luma$weight_b;
    wire  luma$word_valid;
    wire  [31:0] luma$word;
    reg  out_valid$d;
    wire  out_valid$q;
    reg  out_valid$clock;
    reg  [31:0] out_word$d;
    wire  [31:0] out_word$q;
    reg  out_word$clock;
    
    // Local signals
    reg  [31:0] raw_even;
    reg  [31:0] raw_odd;
    
    // Sub module instances
    skylux_core$capture$grouper$quads quads(
        .clock(quads$clock),
        .pixel(quads$pixel),
        .pixel_valid(quads$pixel_valid),
        .line_start(quads$line_start),
        .frame_start(quads$frame_start),
        .raw(quads$raw),
        .quad_valid(quads$quad_valid),
        .pair_valid(quads$pair_valid),
        .top_left(quads$top_left),
        .top_right(quads$top_right),
        .bottom_left(quads$bottom_left),
        .bottom_right(quads$bottom_right)
    );
    skylux_core$capture$grouper$luma luma(
        .clock(luma$clock),
        .quad_valid(luma$quad_valid),
        .top_left(luma$top_left),
        .top_right(luma$top_right),
        .bottom_left(luma$bottom_left),
        .bottom_right(luma$bottom_right),
        .phase(luma$phase),
        .black(luma$black),
        .valid_min(luma$valid_min),
        .valid_max(luma$valid_max),
        .weight_r(luma$weight_r),
        .weight_g(luma$weight_g),
        .weight_b(luma$weight_b),
        .word_valid(luma$word_valid),
        .word(luma$word)
    );
    skylux_core$capture$grouper$out_valid out_valid(
        .d(out_valid$d),
        .q(out_valid$q),
        .clock(out_valid$clock)
    );
    skylux_core$capture$grouper$out_word out_word(
        .d(out_word$d),
        .q(out_word$q),
        .clock(out_word$clock)
    );
    
    // Update code
    always @(*) begin
        out_valid$clock = clock;
        out_word$clock = clock;
        out_valid$d = out_valid$q;
        out_word$d = out_word$q;
        quads$clock = clock;
        luma$clock = clock;
        quads$pixel = pixel;
        quads$pixel_valid = pixel_valid;
        quads$line_start = line_start;
        quads$frame_start = frame_start;
        quads$raw = raw;
        luma$quad_valid = quads$quad_valid;
        luma$top_left = quads$top_left;
        luma$top_right = quads$top_right;
        luma$bottom_left = quads$bottom_left;
        luma$bottom_right = quads$bottom_right;
        luma$phase = phase;
        luma$black = black;
        luma$valid_min = valid_min;
        luma$valid_max = valid_max;
        luma$weight_r = weight_r;
        luma$weight_g = weight_g;
        luma$weight_b = weight_b;
        raw_even = ((quads$top_left) & 32'hffffffff);
        raw_odd = ((quads$top_right) & 32'hffffffff);
        out_valid$d = luma$word_valid | quads$pair_valid;
        if (luma$word_valid) begin
            out_word$d = luma$word;
        end
        else if (quads$pair_valid) begin
            out_word$d = raw_even | (raw_odd << 32'h10);
        end
        word = out_word$q;
        word_valid = out_valid$q;
    end
    
endmodule // skylux_core$capture$grouper


module skylux_core$capture$grouper$luma(clock,quad_valid,top_left,top_right,bottom_left,bottom_right,phase,black,valid_min,valid_max,weight_r,weight_g,weight_b,word_valid,word);
    
    // Module arguments
    input wire  clock;
    input wire  quad_valid;
    input wire  [11:0] top_left;
    input wire  [11:0] top_right;
    input wire  [11:0] bottom_left;
    input wire  [11:0] bottom_right;
    input wire  [1:0] phase;
    input wire  [11:0] black;
    input wire  [11:0] valid_min;
    input wire  [11:0] valid_max;
    input wire  [15:0] weight_r;
    input wire  [15:0] weight_g;
    input wire  [15:0] weight_b;
    output reg  word_valid;
    output reg  [31:0] word;
    
    // Constant declarations
    localparam  under_flag = 32'h40000000;
    localparam  over_flag = 32'h80000000;
    
    // Stub signals
    reg  s1_valid$d;
    wire  s1_valid$q;
    reg  s1_valid$clock;
    reg  s1_under$d;
    wire  s1_under$q;
    reg  s1_under$clock;
    reg  s1_over$d;
    wire  s1_over$q;
    reg  s1_over$clock;
    reg  [15:0] s1_red$d;
    wire  [15:0] s1_red$q;
    reg  s1_red$clock;
    reg  [15:0] s1_green_sum$d;
    wire  [15:0] s1_green_sum$q;
    reg  s1_green_sum$clock;
    reg  [15:0] s1_blue$d;
    wire  [15:0] s1_blue$q;
    reg  s1_blue$clock;
    reg  s2_valid$d;
    wire  s2_valid$q;
    reg  s2_valid$clock;
    reg  s2_under$d;
    wire  s2_under$q;
    reg  s2_under$clock;
    reg  s2_over$d;
    wire  s2_over$q;
    reg  s2_over$clock;
    reg  [31:0] s2_red$d;
    wire  [31:0] s2_red$q;
    reg  s2_red$clock;
    reg  [31:0] s2_green$d;
    wire  [31:0] s2_green$q;
    reg  s2_green$clock;
    reg  [31:0] s2_blue$d;
    wire  [31:0] s2_blue$q;
    reg  s2_blue$clock;
    
    // Local signals
    reg  [11:0] tl_net;
    reg  [11:0] tr_net;
    reg  [11:0] bl_net;
    reg  [11:0] br_net;
    reg  [11:0] red;
    reg  [11:0] blue;
    reg  [11:0] green_1;
    reg  [11:0] green_2;
    reg  [31:0] weighted_sum;
    reg  [31:0] under_bits;
    reg  [31:0] over_bits;
    
    // Sub module instances
    skylux_core$capture$grouper$luma$s1_valid s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    skylux_core$capture$grouper$luma$s1_under s1_under(
        .d(s1_under$d),
        .q(s1_under$q),
        .clock(s1_under$clock)
    );
    skylux_core$capture$grouper$luma$s1_over s1_over(
        .d(s1_over$d),
        .q(s1_over$q),
        .clock(s1_over$clock)
    );
    skylux_core$capture$grouper$luma$s1_red s1_red(
        .d(s1_red$d),
        .q(s1_red$q),
        .clock(s1_red$clock)
    );
    skylux_core$capture$grouper$luma$s1_green_sum s1_green_sum(
        .d(s1_green_sum$d),
        .q(s1_green_sum$q),
        .clock(s1_green_sum$clock)
    );
    skylux_core$capture$grouper$luma$s1_blue s1_blue(
        .d(s1_blue$d),
        .q(s1_blue$q),
        .clock(s1_blue$clock)
    );
    skylux_core$capture$grouper$luma$s2_valid s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    skylux_core$capture$grouper$luma$s2_under s2_under(
        .d(s2_under$d),
        .q(s2_under$q),
        .clock(s2_under$clock)
    );
    skylux_core$capture$grouper$luma$s2_over s2_over(
        .d(s2_over$d),
        .q(s2_over$q),
        .clock(s2_over$clock)
    );
    skylux_core$capture$grouper$luma$s2_red s2_red(
        .d(s2_red$d),
        .q(s2_red$q),
        .clock(s2_red$clock)
    );
    skylux_core$capture$grouper$luma$s2_green s2_green(
        .d(s2_green$d),
        .q(s2_green$q),
        .clock(s2_green$clock)
    );
    skylux_core$capture$grouper$luma$s2_blue s2_blue(
        .d(s2_blue$d),
        .q(s2_blue$q),
        .clock(s2_blue$clock)
    );
    
    // Update code
    always @(*) begin
        s1_valid$clock = clock;
        s1_under$clock = clock;
        s1_over$clock = clock;
        s1_red$clock = clock;
        s1_green_sum$clock = clock;
        s1_blue$clock = clock;
        s2_valid$clock = clock;
        s2_under$clock = clock;
        s2_over$clock = clock;
        s2_red$clock = clock;
        s2_green$clock = clock;
        s2_blue$clock = clock;
        s1_valid$d = s1_valid$q;
        s1_under$d = s1_under$q;
        s1_over$d = s1_over$q;
        s1_red$d = s1_red$q;
        s1_green_sum$d = s1_green_sum$q;
        s1_blue$d = s1_blue$q;
        s2_valid$d = s2_valid$q;
        s2_under$d = s2_under$q;
        s2_over$d = s2_over$q;
        s2_red$d = s2_red$q;
        s2_green$d = s2_green$q;
        s2_blue$d = s2_blue$q;
        s1_valid$d = quad_valid;
        s1_under$d = (top_left < valid_min) | (top_right < valid_min) | (bottom_left < valid_min) | (bottom_right < valid_min);
        s1_over$d = (top_left > valid_max) | (top_right > valid_max) | (bottom_left > valid_max) | (bottom_right > valid_max);
        tl_net = 32'h0;
        if (top_left > black) begin
            tl_net = top_left - black;
        end
        tr_net = 32'h0;
        if (top_right > black) begin
            tr_net = top_right - black;
        end
        bl_net = 32'h0;
        if (bottom_left > black) begin
            bl_net = bottom_left - black;
        end
        br_net = 32'h0;
        if (bottom_right > black) begin
            br_net = bottom_right - black;
        end
        case (phase)
            0:
                begin
                    red = tr_net;
                    blue = bl_net;
                    green_1 = tl_net;
                    green_2 = br_net;
                end
            1:
                begin
                    red = tl_net;
                    blue = br_net;
                    green_1 = tr_net;
                    green_2 = bl_net;
                end
            2:
                begin
                    red = br_net;
                    blue = tl_net;
                    green_1 = tr_net;
                    green_2 = bl_net;
                end
            default:
                begin
                    red = bl_net;
                    blue = tr_net;
                    green_1 = tl_net;
                    green_2 = br_net;
                end
        endcase
        s1_red$d = ((red) & 16'hffff);
        s1_blue$d = ((blue) & 16'hffff);
        s1_green_sum$d = ((green_1) & 16'hffff) + ((green_2) & 16'hffff);
        s2_valid$d = s1_valid$q;
        s2_under$d = s1_under$q;
        s2_over$d = s1_over$q;
        s2_red$d = s1_red$q * weight_r;
        s2_green$d = s1_green_sum$q * weight_g;
        s2_blue$d = s1_blue$q * weight_b;
        weighted_sum = s2_red$q + (s2_green$q >> 32'h1) + s2_blue$q;
        under_bits = 32'h0;
        if (s2_under$q) begin
            under_bits = under_flag;
        end
        over_bits = 32'h0;
        if (s2_over$q) begin
            over_bits = over_flag;
        end
        word = weighted_sum | under_bits | over_bits;
        word_valid = s2_valid$q;
    end
    
endmodule // skylux_core$capture$grouper$luma


module skylux_core$capture$grouper$luma$s1_blue(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$luma$s1_blue


module skylux_core$capture$grouper$luma$s1_green_sum(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$luma$s1_green_sum


module skylux_core$capture$grouper$luma$s1_over(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$luma$s1_over


module skylux_core$capture$grouper$luma$s1_red(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$luma$s1_red


module skylux_core$capture$grouper$luma$s1_under(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$luma$s1_under


module skylux_core$capture$grouper$luma$s1_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$luma$s1_valid


module skylux_core$capture$grouper$luma$s2_blue(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$luma$s2_blue


module skylux_core$capture$grouper$luma$s2_green(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$luma$s2_green


module skylux_core$capture$grouper$luma$s2_over(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$luma$s2_over


module skylux_core$capture$grouper$luma$s2_red(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$luma$s2_red


module skylux_core$capture$grouper$luma$s2_under(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$luma$s2_under


module skylux_core$capture$grouper$luma$s2_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$luma$s2_valid


module skylux_core$capture$grouper$out_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$out_valid


module skylux_core$capture$grouper$out_word(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$out_word


module skylux_core$capture$grouper$quads(clock,pixel,pixel_valid,line_start,frame_start,raw,quad_valid,pair_valid,top_left,top_right,bottom_left,bottom_right);
    
    // Module arguments
    input wire  clock;
    input wire  [11:0] pixel;
    input wire  pixel_valid;
    input wire  line_start;
    input wire  frame_start;
    input wire  raw;
    output reg  quad_valid;
    output reg  pair_valid;
    output reg  [11:0] top_left;
    output reg  [11:0] top_right;
    output reg  [11:0] bottom_left;
    output reg  [11:0] bottom_right;
    
    // Stub signals
    reg  [11:0] line_buffer$read_address;
    reg  line_buffer$read_clock;
    wire  [11:0] line_buffer$read_data;
    reg  [11:0] line_buffer$write_address;
    reg  line_buffer$write_clock;
    reg  [11:0] line_buffer$write_data;
    reg  line_buffer$write_enable;
    reg  in_valid$d;
    wire  in_valid$q;
    reg  in_valid$clock;
    reg  [11:0] in_pixel$d;
    wire  [11:0] in_pixel$q;
    reg  in_pixel$clock;
    reg  in_line_start$d;
    wire  in_line_start$q;
    reg  in_line_start$clock;
    reg  in_frame_start$d;
    wire  in_frame_start$q;
    reg  in_frame_start$clock;
    reg  [11:0] next_column$d;
    wire  [11:0] next_column$q;
    reg  next_column$clock;
    reg  bottom_line$d;
    wire  bottom_line$q;
    reg  bottom_line$clock;
    reg  at_valid$d;
    wire  at_valid$q;
    reg  at_valid$clock;
    reg  [11:0] at_pixel$d;
    wire  [11:0] at_pixel$q;
    reg  at_pixel$clock;
    reg  at_odd_column$d;
    wire  at_odd_column$q;
    reg  at_odd_column$clock;
    reg  at_bottom$d;
    wire  at_bottom$q;
    reg  at_bottom$clock;
    reg  [11:0] even_pixel$d;
    wire  [11:0] even_pixel$q;
    reg  even_pixel$clock;
    reg  [11:0] even_above$d;
    wire  [11:0] even_above$q;
    reg  even_above$clock;
    reg  out_quad$d;
    wire  out_quad$q;
    reg  out_quad$clock;
    reg  out_pair$d;
    wire  out_pair$q;
    reg  out_pair$clock;
    reg  [11:0] out_top_left$d;
    wire  [11:0] out_top_left$q;
    reg  out_top_left$clock;
    reg  [11:0] out_top_right$d;
    wire  [11:0] out_top_right$q;
    reg  out_top_right$clock;
    reg  [11:0] out_bottom_left$d;
    wire  [11:0] out_bottom_left$q;
    reg  out_bottom_left$clock;
    reg  [11:0] out_bottom_right$d;
    wire  [11:0] out_bottom_right$q;
    reg  out_bottom_right$clock;
    
    // Local signals
    reg  [11:0] column;
    reg  bottom;
    reg  [11:0] above;
    
    // Sub module instances
    skylux_core$capture$grouper$quads$line_buffer line_buffer(
        .read_address(line_buffer$read_address),
        .read_clock(line_buffer$read_clock),
        .read_data(line_buffer$read_data),
        .write_address(line_buffer$write_address),
        .write_clock(line_buffer$write_clock),
        .write_data(line_buffer$write_data),
        .write_enable(line_buffer$write_enable)
    );
    skylux_core$capture$grouper$quads$in_valid in_valid(
        .d(in_valid$d),
        .q(in_valid$q),
        .clock(in_valid$clock)
    );
    skylux_core$capture$grouper$quads$in_pixel in_pixel(
        .d(in_pixel$d),
        .q(in_pixel$q),
        .clock(in_pixel$clock)
    );
    skylux_core$capture$grouper$quads$in_line_start in_line_start(
        .d(in_line_start$d),
        .q(in_line_start$q),
        .clock(in_line_start$clock)
    );
    skylux_core$capture$grouper$quads$in_frame_start in_frame_start(
        .d(in_frame_start$d),
        .q(in_frame_start$q),
        .clock(in_frame_start$clock)
    );
    skylux_core$capture$grouper$quads$next_column next_column(
        .d(next_column$d),
        .q(next_column$q),
        .clock(next_column$clock)
    );
    skylux_core$capture$grouper$quads$bottom_line bottom_line(
        .d(bottom_line$d),
        .q(bottom_line$q),
        .clock(bottom_line$clock)
    );
    skylux_core$capture$grouper$quads$at_valid at_valid(
        .d(at_valid$d),
        .q(at_valid$q),
        .clock(at_valid$clock)
    );
    skylux_core$capture$grouper$quads$at_pixel at_pixel(
        .d(at_pixel$d),
        .q(at_pixel$q),
        .clock(at_pixel$clock)
    );
    skylux_core$capture$grouper$quads$at_odd_column at_odd_column(
        .d(at_odd_column$d),
        .q(at_odd_column$q),
        .clock(at_odd_column$clock)
    );
    skylux_core$capture$grouper$quads$at_bottom at_bottom(
        .d(at_bottom$d),
        .q(at_bottom$q),
        .clock(at_bottom$clock)
    );
    skylux_core$capture$grouper$quads$even_pixel even_pixel(
        .d(even_pixel$d),
        .q(even_pixel$q),
        .clock(even_pixel$clock)
    );
    skylux_core$capture$grouper$quads$even_above even_above(
        .d(even_above$d),
        .q(even_above$q),
        .clock(even_above$clock)
    );
    skylux_core$capture$grouper$quads$out_quad out_quad(
        .d(out_quad$d),
        .q(out_quad$q),
        .clock(out_quad$clock)
    );
    skylux_core$capture$grouper$quads$out_pair out_pair(
        .d(out_pair$d),
        .q(out_pair$q),
        .clock(out_pair$clock)
    );
    skylux_core$capture$grouper$quads$out_top_left out_top_left(
        .d(out_top_left$d),
        .q(out_top_left$q),
        .clock(out_top_left$clock)
    );
    skylux_core$capture$grouper$quads$out_top_right out_top_right(
        .d(out_top_right$d),
        .q(out_top_right$q),
        .clock(out_top_right$clock)
    );
    skylux_core$capture$grouper$quads$out_bottom_left out_bottom_left(
        .d(out_bottom_left$d),
        .q(out_bottom_left$q),
        .clock(out_bottom_left$clock)
    );
    skylux_core$capture$grouper$quads$out_bottom_right out_bottom_right(
        .d(out_bottom_right$d),
        .q(out_bottom_right$q),
        .clock(out_bottom_right$clock)
    );
    
    // Update code
    always @(*) begin
        in_valid$clock = clock;
        in_pixel$clock = clock;
        in_line_start$clock = clock;
        in_frame_start$clock = clock;
        next_column$clock = clock;
        bottom_line$clock = clock;
        at_valid$clock = clock;
        at_pixel$clock = clock;
        at_odd_column$clock = clock;
        at_bottom$clock = clock;
        even_pixel$clock = clock;
        even_above$clock = clock;
        out_quad$clock = clock;
        out_pair$clock = clock;
        out_top_left$clock = clock;
        out_top_right$clock = clock;
        out_bottom_left$clock = clock;
        out_bottom_right$clock = clock;
        in_valid$d = in_valid$q;
        in_pixel$d = in_pixel$q;
        in_line_start$d = in_line_start$q;
        in_frame_start$d = in_frame_start$q;
        next_column$d = next_column$q;
        bottom_line$d = bottom_line$q;
        at_valid$d = at_valid$q;
        at_pixel$d = at_pixel$q;
        at_odd_column$d = at_odd_column$q;
        at_bottom$d = at_bottom$q;
        even_pixel$d = even_pixel$q;
        even_above$d = even_above$q;
        out_quad$d = out_quad$q;
        out_pair$d = out_pair$q;
        out_top_left$d = out_top_left$q;
        out_top_right$d = out_top_right$q;
        out_bottom_left$d = out_bottom_left$q;
        out_bottom_right$d = out_bottom_right$q;
        line_buffer$read_clock = clock;
        line_buffer$write_clock = clock;
        in_valid$d = pixel_valid;
        in_pixel$d = pixel;
        in_line_start$d = line_start | frame_start;
        in_frame_start$d = frame_start;
        column = next_column$q;
        bottom = bottom_line$q;
        if (in_line_start$q) begin
            column = 32'h0;
            bottom = ~bottom_line$q;
        end
        if (in_frame_start$q) begin
            bottom = 1'b0;
        end
        if (in_valid$q) begin
            next_column$d = column + 32'h1;
            bottom_line$d = bottom;
        end
        line_buffer$write_address = column;
        line_buffer$write_data = in_pixel$q;
        line_buffer$write_enable = in_valid$q & ~bottom & ~raw;
        line_buffer$read_address = column;
        at_valid$d = in_valid$q;
        at_pixel$d = in_pixel$q;
        at_odd_column$d = column[32'h0];
        at_bottom$d = bottom;
        above = line_buffer$read_data;
        out_quad$d = 1'b0;
        out_pair$d = 1'b0;
        if (at_valid$q & ~at_odd_column$q) begin
            even_pixel$d = at_pixel$q;
            even_above$d = above;
        end
        if (at_valid$q & at_odd_column$q) begin
            if (raw) begin
                out_pair$d = 1'b1;
                out_top_left$d = even_pixel$q;
                out_top_right$d = at_pixel$q;
            end
            else if (at_bottom$q) begin
                out_quad$d = 1'b1;
                out_top_left$d = even_above$q;
                out_top_right$d = above;
                out_bottom_left$d = even_pixel$q;
                out_bottom_right$d = at_pixel$q;
            end
        end
        quad_valid = out_quad$q;
        pair_valid = out_pair$q;
        top_left = out_top_left$q;
        top_right = out_top_right$q;
        bottom_left = out_bottom_left$q;
        bottom_right = out_bottom_right$q;
    end
    
endmodule // skylux_core$capture$grouper$quads


module skylux_core$capture$grouper$quads$at_bottom(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$quads$at_bottom


module skylux_core$capture$grouper$quads$at_odd_column(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$quads$at_odd_column


module skylux_core$capture$grouper$quads$at_pixel(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$quads$at_pixel


module skylux_core$capture$grouper$quads$at_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$quads$at_valid


module skylux_core$capture$grouper$quads$bottom_line(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$quads$bottom_line


module skylux_core$capture$grouper$quads$even_above(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$quads$even_above


module skylux_core$capture$grouper$quads$even_pixel(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$quads$even_pixel


module skylux_core$capture$grouper$quads$in_frame_start(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$quads$in_frame_start


module skylux_core$capture$grouper$quads$in_line_start(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$quads$in_line_start


module skylux_core$capture$grouper$quads$in_pixel(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$quads$in_pixel


module skylux_core$capture$grouper$quads$in_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$quads$in_valid


module skylux_core$capture$grouper$quads$line_buffer(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [11:0] read_address;
    input wire  read_clock;
    output reg  [11:0] read_data;
    input wire  [11:0] write_address;
    input wire  write_clock;
    input wire  [11:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[11:0] mem[4095:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // skylux_core$capture$grouper$quads$line_buffer


module skylux_core$capture$grouper$quads$next_column(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$quads$next_column


module skylux_core$capture$grouper$quads$out_bottom_left(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$quads$out_bottom_left


module skylux_core$capture$grouper$quads$out_bottom_right(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$quads$out_bottom_right


module skylux_core$capture$grouper$quads$out_pair(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$quads$out_pair


module skylux_core$capture$grouper$quads$out_quad(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$quads$out_quad


module skylux_core$capture$grouper$quads$out_top_left(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$quads$out_top_left


module skylux_core$capture$grouper$quads$out_top_right(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$grouper$quads$out_top_right


module skylux_core$capture$ingest(clock,fifo_data,fifo_empty,fifo_fill,fifo_read,frame_valid_async,heartbeat_async,enable,raw,tag_exposure_index,tag_frame_number,tag_timestamp,hdr_enable,hdr_new_set,hdr_min_q11,hdr_max_q11,writer_idle,frame_closed,beat_room,beat_push,beat_data,beat_byteenable,frame_open,frame_ended,desc_frame_number,desc_timestamp,desc_info,desc_geometry,desc_words,desc_checksum,capture_status_frame_valid,capture_status_line_short_set,capture_status_line_long_set,capture_status_frame_short_set,capture_status_frame_long_set,capture_status_fifo_overflow_set,capture_status_pixclk_stopped_set,capture_last_frame_pixels,capture_last_frame_lines,capture_fifo_high_water_words,capture_frames_count,dma_status_overflow_set,taken_valid,taken_word,taken_first,taken_exposure_index);
    
    // Module arguments
    input wire  clock;
    input wire  [33:0] fifo_data;
    input wire  fifo_empty;
    input wire  [7:0] fifo_fill;
    output reg  fifo_read;
    input wire  frame_valid_async;
    input wire  heartbeat_async;
    input wire  enable;
    input wire  raw;
    input wire  [2:0] tag_exposure_index;
    input wire  [31:0] tag_frame_number;
    input wire  [63:0] tag_timestamp;
    input wire  hdr_enable;
    input wire  hdr_new_set;
    input wire  [26:0] hdr_min_q11;
    input wire  [26:0] hdr_max_q11;
    input wire  writer_idle;
    input wire  frame_closed;
    input wire  beat_room;
    output reg  beat_push;
    output reg  [63:0] beat_data;
    output reg  [7:0] beat_byteenable;
    output reg  frame_open;
    output reg  frame_ended;
    output reg  [31:0] desc_frame_number;
    output reg  [63:0] desc_timestamp;
    output reg  [31:0] desc_info;
    output reg  [31:0] desc_geometry;
    output reg  [31:0] desc_words;
    output reg  [31:0] desc_checksum;
    output reg  capture_status_frame_valid;
    output reg  capture_status_line_short_set;
    output reg  capture_status_line_long_set;
    output reg  capture_status_frame_short_set;
    output reg  capture_status_frame_long_set;
    output reg  capture_status_fifo_overflow_set;
    output reg  capture_status_pixclk_stopped_set;
    output reg  [11:0] capture_last_frame_pixels;
    output reg  [11:0] capture_last_frame_lines;
    output reg  [15:0] capture_fifo_high_water_words;
    output reg  [31:0] capture_frames_count;
    output reg  dma_status_overflow_set;
    output reg  taken_valid;
    output reg  [31:0] taken_word;
    output reg  taken_first;
    output reg  [2:0] taken_exposure_index;
    
    // Enums
    localparam IngestState$Idle = 0;
    localparam IngestState$Frame = 1;
    localparam IngestState$Ended = 2;
    
    // Stub signals
    reg  hdr$clock;
    reg  hdr$restart;
    reg  hdr$first_of_set;
    reg  [2:0] hdr$exposure_index;
    reg  hdr$take;
    reg  [31:0] hdr$word;
    reg  [26:0] hdr$min_q11;
    reg  [26:0] hdr$max_q11;
    wire  [31:0] hdr$map_word;
    wire  hdr$map_write;
    wire  hdr$map_settles;
    reg  [1:0] state$d;
    wire  [1:0] state$q;
    reg  state$clock;
    reg  fv_meta$d;
    wire  fv_meta$q;
    reg  fv_meta$clock;
    reg  fv_sync$d;
    wire  fv_sync$q;
    reg  fv_sync$clock;
    reg  fv_prev$d;
    wire  fv_prev$q;
    reg  fv_prev$clock;
    reg  hb_meta$d;
    wire  hb_meta$q;
    reg  hb_meta$clock;
    reg  hb_sync$d;
    wire  hb_sync$q;
    reg  hb_sync$clock;
    reg  hb_prev$d;
    wire  hb_prev$q;
    reg  hb_prev$clock;
    reg  [10:0] since_heartbeat$d;
    wire  [10:0] since_heartbeat$q;
    reg  since_heartbeat$clock;
    reg  [2:0] pending_exposure$d;
    wire  [2:0] pending_exposure$q;
    reg  pending_exposure$clock;
    reg  [31:0] pending_frame_number$d;
    wire  [31:0] pending_frame_number$q;
    reg  pending_frame_number$clock;
    reg  [63:0] pending_timestamp$d;
    wire  [63:0] pending_timestamp$q;
    reg  pending_timestamp$clock;
    reg  [31:0] frame_number$d;
    wire  [31:0] frame_number$q;
    reg  frame_number$clock;
    reg  [63:0] timestamp$d;
    wire  [63:0] timestamp$q;
    reg  timestamp$clock;
    reg  [31:0] info$d;
    wire  [31:0] info$q;
    reg  info$clock;
    reg  [31:0] geometry$d;
    wire  [31:0] geometry$q;
    reg  geometry$clock;
    reg  [31:0] words$d;
    wire  [31:0] words$q;
    reg  words$clock;
    reg  [31:0] checksum$d;
    wire  [31:0] checksum$q;
    reg  checksum$clock;
    reg  [31:0] half$d;
    wire  [31:0] half$q;
    reg  half$clock;
    reg  half_valid$d;
    wire  half_valid$q;
    reg  half_valid$clock;
    reg  [3:0] half_enables$d;
    wire  [3:0] half_enables$q;
    reg  half_enables$clock;
    reg  hdr_frame$d;
    wire  hdr_frame$q;
    reg  hdr_frame$clock;
    reg  new_set_pending$d;
    wire  new_set_pending$q;
    reg  new_set_pending$clock;
    reg  [2:0] set_ordinal$d;
    wire  [2:0] set_ordinal$q;
    reg  set_ordinal$clock;
    reg  [31:0] set_sum$d;
    wire  [31:0] set_sum$q;
    reg  set_sum$clock;
    reg  [7:0] high_water$d;
    wire  [7:0] high_water$q;
    reg  high_water$clock;
    reg  [7:0] last_high_water$d;
    wire  [7:0] last_high_water$q;
    reg  last_high_water$clock;
    reg  [11:0] last_pixels$d;
    wire  [11:0] last_pixels$q;
    reg  last_pixels$clock;
    reg  [11:0] last_lines$d;
    wire  [11:0] last_lines$q;
    reg  last_lines$clock;
    reg  [31:0] frames$d;
    wire  [31:0] frames$q;
    reg  frames$clock;
    
    // Local signals
    reg  is_marker;
    reg  is_end;
    reg  is_start;
    reg  is_data;
    reg  [31:0] payload;
    reg  [31:0] info_start;
    reg  pixclk_stopped;
    reg  close_now;
    reg  [31:0] marker_flags;
    reg  [31:0] out_word;
    reg  [3:0] out_enables;
    reg  [2:0] next_ordinal;
    
    // Sub module instances
    skylux_core$capture$ingest$hdr hdr(
        .clock(hdr$clock),
        .restart(hdr$restart),
        .first_of_set(hdr$first_of_set),
        .exposure_index(hdr$exposure_index),
        .take(hdr$take),
        .word(hdr$word),
        .min_q11(hdr$min_q11),
        .max_q11(hdr$max_q11),
        .map_word(hdr$map_word),
        .map_write(hdr$map_write),
        .map_settles(hdr$map_settles)
    );
    skylux_core$capture$ingest$state state(
        .d(state$d),
        .q(state$q),
        .clock(state$clock)
    );
    skylux_core$capture$ingest$fv_meta fv_meta(
        .d(fv_meta$d),
        .q(fv_meta$q),
        .clock(fv_meta$clock)
    );
    skylux_core$capture$ingest$fv_sync fv_sync(
        .d(fv_sync$d),
        .q(fv_sync$q),
        .clock(fv_sync$clock)
    );
    skylux_core$capture$ingest$fv_prev fv_prev(
        .d(fv_prev$d),
        .q(fv_prev$q),
        .clock(fv_prev$clock)
    );
    skylux_core$capture$ingest$hb_meta hb_meta(
        .d(hb_meta$d),
        .q(hb_meta$q),
        .clock(hb_meta$clock)
    );
    skylux_core$capture$ingest$hb_sync hb_sync(
        .d(hb_sync$d),
        .q(hb_sync$q),
        .clock(hb_sync$clock)
    );
    skylux_core$capture$ingest$hb_prev hb_prev(
        .d(hb_prev$d),
        .q(hb_prev$q),
        .clock(hb_prev$clock)
    );
    skylux_core$capture$ingest$since_heartbeat since_heartbeat(
        .d(since_heartbeat$d),
        .q(since_heartbeat$q),
        .clock(since_heartbeat$clock)
    );
    skylux_core$capture$ingest$pending_exposure pending_exposure(
        .d(pending_exposure$d),
        .q(pending_exposure$q),
        .clock(pending_exposure$clock)
    );
    skylux_core$capture$ingest$pending_frame_number pending_frame_number(
        .d(pending_frame_number$d),
        .q(pending_frame_number$q),
        .clock(pending_frame_number$clock)
    );
    skylux_core$capture$ingest$pending_timestamp pending_timestamp(
        .d(pending_timestamp$d),
        .q(pending_timestamp$q),
        .clock(pending_timestamp$clock)
    );
    skylux_core$capture$ingest$frame_number frame_number(
        .d(frame_number$d),
        .q(frame_number$q),
        .clock(frame_number$clock)
    );
    skylux_core$capture$ingest$timestamp timestamp(
        .d(timestamp$d),
        .q(timestamp$q),
        .clock(timestamp$clock)
    );
    skylux_core$capture$ingest$info info(
        .d(info$d),
        .q(info$q),
        .clock(info$clock)
    );
    skylux_core$capture$ingest$geometry geometry(
        .d(geometry$d),
        .q(geometry$q),
        .clock(geometry$clock)
    );
    skylux_core$capture$ingest$words words(
        .d(words$d),
        .q(words$q),
        .clock(words$clock)
    );
    skylux_core$capture$ingest$checksum checksum(
        .d(checksum$d),
        .q(checksum$q),
        .clock(checksum$clock)
    );
    skylux_core$capture$ingest$half half(
        .d(half$d),
        .q(half$q),
        .clock(half$clock)
    );
    skylux_core$capture$ingest$half_valid half_valid(
        .d(half_valid$d),
        .q(half_valid$q),
        .clock(half_valid$clock)
    );
    skylux_core$capture$ingest$half_enables half_enables(
        .d(half_enables$d),
        .q(half_enables$q),
        .clock(half_enables$clock)
    );
    skylux_core$capture$ingest$hdr_frame hdr_frame(
        .d(hdr_frame$d),
        .q(hdr_frame$q),
        .clock(hdr_frame$clock)
    );
    skylux_core$capture$ingest$new_set_pending new_set_pending(
        .d(new_set_pending$d),
        .q(new_set_pending$q),
        .clock(new_set_pending$clock)
    );
    skylux_core$capture$ingest$set_ordinal set_ordinal(
        .d(set_ordinal$d),
        .q(set_ordinal$q),
        .clock(set_ordinal$clock)
    );
    skylux_core$capture$ingest$set_sum set_sum(
        .d(set_sum$d),
        .q(set_sum$q),
        .clock(set_sum$clock)
    );
    skylux_core$capture$ingest$high_water high_water(
        .d(high_water$d),
        .q(high_water$q),
        .clock(high_water$clock)
    );
    skylux_core$capture$ingest$last_high_water last_high_water(
        .d(last_high_water$d),
        .q(last_high_water$q),
        .clock(last_high_water$clock)
    );
    skylux_core$capture$ingest$last_pixels last_pixels(
        .d(last_pixels$d),
        .q(last_pixels$q),
        .clock(last_pixels$clock)
    );
    skylux_core$capture$ingest$last_lines last_lines(
        .d(last_lines$d),
        .q(last_lines$q),
        .clock(last_lines$clock)
    );
    skylux_core$capture$ingest$frames frames(
        .d(frames$d),
        .q(frames$q),
        .clock(frames$clock)
    );
    
    // Update code
    always @(*) begin
        state$clock = clock;
        fv_meta$clock = clock;
        fv_sync$clock = clock;
        fv_prev$clock = clock;
        hb_meta$clock = clock;
        hb_sync$clock = clock;
        hb_prev$clock = clock;
        since_heartbeat$clock = clock;
        pending_exposure$clock = clock;
        pending_frame_number$clock = clock;
        pending_timestamp$clock = clock;
        frame_number$clock = clock;
        timestamp$clock = clock;
        info$clock = clock;
        geometry$clock = clock;
        words$clock = clock;
        checksum$clock = clock;
        half$clock = clock;
        half_valid$clock = clock;
        half_enables$clock = clock;
        hdr_frame$clock = clock;
        new_set_pending$clock = clock;
        set_ordinal$clock = clock;
        set_sum$clock = clock;
        high_water$clock = clock;
        last_high_water$clock = clock;
        last_pixels$clock = clock;
        last_lines$clock = clock;
        frames$clock = clock;
        state$d = state$q;
        fv_meta$d = fv_meta$q;
        fv_sync$d = fv_sync$q;
        fv_prev$d = fv_prev$q;
        hb_meta$d = hb_meta$q;
        hb_sync$d = hb_sync$q;
        hb_prev$d = hb_prev$q;
        since_heartbeat$d = since_heartbeat$q;
        pending_exposure$d = pending_exposure$q;
        pending_frame_number$d = pending_frame_number$q;
        pending_timestamp$d = pending_timestamp$q;
        frame_number$d = frame_number$q;
        timestamp$d = timestamp$q;
        info$d = info$q;
        geometry$d = geometry$q;
        words$d = words$q;
        checksum$d = checksum$q;
        half$d = half$q;
        half_valid$d = half_valid$q;
        half_enables$d = half_enables$q;
        hdr_frame$d = hdr_frame$q;
        new_set_pending$d = new_set_pending$q;
        set_ordinal$d = set_ordinal$q;
        set_sum$d = set_sum$q;
        high_water$d = high_water$q;
        last_high_water$d = last_high_water$q;
        last_pixels$d = last_pixels$q;
        last_lines$d = last_lines$q;
        frames$d = frames$q;
        fv_meta$d = frame_valid_async;
        fv_sync$d = fv_meta$q;
        fv_prev$d = fv_sync$q;
        hb_meta$d = heartbeat_async;
        hb_sync$d = hb_meta$q;
        hb_prev$d = hb_sync$q;
        if (hb_sync$q != hb_prev$q) begin
            since_heartbeat$d = 32'h0;
        end
        else if (~since_heartbeat$q[32'ha]) begin
            since_heartbeat$d = since_heartbeat$q + 32'h1;
        end
        pixclk_stopped = since_heartbeat$q[32'ha];
        capture_status_frame_valid = fv_sync$q;
        if (fv_sync$q & ~fv_prev$q) begin
            pending_exposure$d = tag_exposure_index;
            pending_frame_number$d = tag_frame_number;
            pending_timestamp$d = tag_timestamp;
        end
        if (fifo_fill > high_water$q) begin
            high_water$d = fifo_fill;
        end
        is_marker = ~fifo_empty & fifo_data[32'h20];
        is_end = is_marker & fifo_data[32'h21];
        is_start = is_marker & ~fifo_data[32'h21];
        is_data = ~fifo_empty & ~fifo_data[32'h20];
        payload = fifo_data[(32'h0)+:(32)];
        marker_flags = 32'h0;
        marker_flags = (marker_flags & ~(1 << (32'h10)) | ((payload[32'h18]) << (32'h10)));
        marker_flags = (marker_flags & ~(1 << (32'h11)) | ((payload[32'h19]) << (32'h11)));
        marker_flags = (marker_flags & ~(1 << (32'h12)) | ((payload[32'h1a]) << (32'h12)));
        marker_flags = (marker_flags & ~(1 << (32'h13)) | ((payload[32'h1b]) << (32'h13)));
        marker_flags = (marker_flags & ~(1 << (32'h14)) | ((payload[32'h1c]) << (32'h14)));
        marker_flags = (marker_flags & ~(1 << (32'h18)) | ((payload[32'h1d]) << (32'h18)));
        fifo_read = 1'b0;
        capture_status_line_short_set = 1'b0;
        capture_status_line_long_set = 1'b0;
        capture_status_frame_short_set = 1'b0;
        capture_status_frame_long_set = 1'b0;
        capture_status_fifo_overflow_set = 1'b0;
        capture_status_pixclk_stopped_set = 1'b0;
        dma_status_overflow_set = 1'b0;
        if (is_end & (state$q != IngestState$Ended)) begin
            capture_status_line_short_set = payload[32'h18];
            capture_status_line_long_set = payload[32'h19];
            capture_status_frame_short_set = payload[32'h1a];
            capture_status_frame_long_set = payload[32'h1b];
            capture_status_fifo_overflow_set = payload[32'h1c];
            last_pixels$d = payload[(32'h0)+:(12)];
            last_lines$d = payload[(32'hc)+:(12)];
            frames$d = frames$q + 32'h1;
            last_high_water$d = high_water$q;
            high_water$d = fifo_fill;
        end
        capture_last_frame_pixels = last_pixels$q;
        capture_last_frame_lines = last_lines$q;
        capture_frames_count = frames$q;
        capture_fifo_high_water_words = ((last_high_water$q) & 16'hffff);
        info_start = ((pending_exposure$q) & 32'hffffffff);
        info_start = (info_start & ~(1 << (32'h8)) | ((raw) << (32'h8)));
        info_start = (info_start & ~(1 << (32'h9)) | ((hdr_enable & ~raw) << (32'h9)));
        hdr$clock = clock;
        hdr$restart = 1'b0;
        if (hdr_new_set) begin
            new_set_pending$d = 1'b1;
        end
        next_ordinal = set_ordinal$q + 32'h1;
        if (set_ordinal$q == 32'h7) begin
            next_ordinal = 32'h7;
        end
        if (new_set_pending$q) begin
            next_ordinal = 32'h0;
        end
        hdr$first_of_set = new_set_pending$q;
        hdr$exposure_index = next_ordinal;
        hdr$take = 1'b0;
        hdr$word = payload;
        hdr$min_q11 = hdr_min_q11;
        hdr$max_q11 = hdr_max_q11;
        out_word = payload;
        out_enables = 32'hf;
        if (hdr_frame$q) begin
            out_word = hdr$map_word;
            if (~hdr$map_write) begin
                out_enables = 32'h0;
            end
        end
        beat_push = 1'b0;
        beat_data = 32'h0;
        beat_byteenable = 32'hff;
        taken_valid = 1'b0;
        taken_word = payload;
        taken_first = words$q == 32'h0;
        taken_exposure_index = info$q[(32'h0)+:(3)];
        frame_open = 1'b0;
        close_now = 1'b0;
        case (state$q)
            IngestState$Idle:
                begin
                    if (is_start) begin
                        if (~enable) begin
                            fifo_read = 1'b1;
                        end
                        else if (writer_idle) begin
                            fifo_read = 1'b1;
                            frame_open = 1'b1;
                            frame_number$d = pending_frame_number$q;
                            timestamp$d = pending_timestamp$q;
                            info$d = info_start;
                            geometry$d = 32'h0;
                            words$d = 32'h0;
                            checksum$d = 32'h0;
                            half_valid$d = 1'b0;
                            hdr$restart = 1'b1;
                            hdr_frame$d = hdr_enable & ~raw;
                            if (hdr_enable & ~raw) begin
                                set_ordinal$d = next_ordinal;
                                new_set_pending$d = 1'b0;
                                if (new_set_pending$q) begin
                                    set_sum$d = 32'h0;
                                end
                            end
                            state$d = IngestState$Frame;
                        end
                    end
                    else if (~fifo_empty) begin
                        fifo_read = 1'b1;
                    end
                end
            IngestState$Frame:
                begin
                    if (is_data) begin
                        if (beat_room) begin
                            fifo_read = 1'b1;
                            taken_valid = 1'b1;
                            hdr$take = 1'b1;
                            words$d = words$q + 32'h1;
                            checksum$d = checksum$q + payload;
                            if (half_valid$q) begin
                                beat_push = 1'b1;
                                beat_data = ((half$q) & 64'hffffffffffffffff) | (((out_word) & 64'hffffffffffffffff) << 32'h20);
                                beat_byteenable = ((half_enables$q) & 8'hff) | (((out_enables) & 8'hff) << 32'h4);
                                half_valid$d = 1'b0;
                            end
                            else begin
                                half$d = out_word;
                                half_enables$d = out_enables;
                                half_valid$d = 1'b1;
                            end
                        end
                    end
                    else if (is_end) begin
                        fifo_read = 1'b1;
                        close_now = 1'b1;
                        info$d = info$q | marker_flags;
                        geometry$d = ((payload[(32'h0)+:(12)]) & 32'hffffffff) | (((payload[(32'hc)+:(12)]) & 32'hffffffff) << 32'h10);
                        dma_status_overflow_set = payload[32'h1c];
                    end
                    else if (is_start) begin
                        close_now = 1'b1;
                        info$d = (info$q & ~(1 << (32'h12)) | ((1'b1) << (32'h12)));
                    end
                    else if (pixclk_stopped) begin
                        close_now = 1'b1;
                        info$d = (info$q & ~(1 << (32'h15)) | ((1'b1) << (32'h15)));
                        capture_status_pixclk_stopped_set = 1'b1;
                    end
                    if (close_now) begin
                        state$d = IngestState$Ended;
                        if (half_valid$q) begin
                            beat_push = 1'b1;
                            beat_data = ((half$q) & 64'hffffffffffffffff);
                            beat_byteenable = ((half_enables$q) & 8'hff) | 32'hf0;
                            half_valid$d = 1'b0;
                        end
                    end
                end
            IngestState$Ended:
                begin
                    if (frame_closed) begin
                        state$d = IngestState$Idle;
                    end
                end
        endcase
        frame_ended = state$q == IngestState$Ended;
        desc_frame_number = frame_number$q;
        desc_timestamp = timestamp$q;
        desc_info = info$q;
        desc_geometry = geometry$q;
        desc_words = words$q;
        desc_checksum = checksum$q;
        if (hdr_frame$q) begin
            desc_checksum = set_sum$q;
        end
        if (hdr_frame$q & hdr$map_settles) begin
            set_sum$d = set_sum$q + hdr$map_word;
        end
    end
    
endmodule // skylux_core$capture$ingest


module skylux_core$capture$ingest$checksum(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$checksum


module skylux_core$capture$ingest$frame_number(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$frame_number


module skylux_core$capture$ingest$frames(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$frames


module skylux_core$capture$ingest$fv_meta(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$fv_meta


module skylux_core$capture$ingest$fv_prev(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$fv_prev


module skylux_core$capture$ingest$fv_sync(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$fv_sync


module skylux_core$capture$ingest$geometry(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$geometry


module skylux_core$capture$ingest$half(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$half


module skylux_core$capture$ingest$half_enables(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$half_enables


module skylux_core$capture$ingest$half_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$half_valid


module skylux_core$capture$ingest$hb_meta(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$hb_meta


module skylux_core$capture$ingest$hb_prev(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$hb_prev


module skylux_core$capture$ingest$hb_sync(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$hb_sync


module skylux_core$capture$ingest$hdr(clock,restart,first_of_set,exposure_index,take,word,min_q11,max_q11,map_word,map_write,map_settles);
    
    // Module arguments
    input wire  clock;
    input wire  restart;
    input wire  first_of_set;
    input wire  [2:0] exposure_index;
    input wire  take;
    input wire  [31:0] word;
    input wire  [26:0] min_q11;
    input wire  [26:0] max_q11;
    output reg  [31:0] map_word;
    output reg  map_write;
    output reg  map_settles;
    
    // Stub signals
    reg  [19:0] mask_low$read_address;
    reg  mask_low$read_clock;
    wire  mask_low$read_data;
    reg  [19:0] mask_low$write_address;
    reg  mask_low$write_clock;
    reg  mask_low$write_data;
    reg  mask_low$write_enable;
    reg  [17:0] mask_high$read_address;
    reg  mask_high$read_clock;
    wire  mask_high$read_data;
    reg  [17:0] mask_high$write_address;
    reg  mask_high$write_clock;
    reg  mask_high$write_data;
    reg  mask_high$write_enable;
    reg  [20:0] pos$d;
    wire  [20:0] pos$q;
    reg  pos$clock;
    reg  set_first$d;
    wire  set_first$q;
    reg  set_first$clock;
    reg  [2:0] index$d;
    wire  [2:0] index$q;
    reg  index$clock;
    
    // Local signals
    reg  [20:0] next_pos;
    reg  [26:0] luma;
    reg  usable;
    reg  filled;
    
    // Sub module instances
    skylux_core$capture$ingest$hdr$mask_low mask_low(
        .read_address(mask_low$read_address),
        .read_clock(mask_low$read_clock),
        .read_data(mask_low$read_data),
        .write_address(mask_low$write_address),
        .write_clock(mask_low$write_clock),
        .write_data(mask_low$write_data),
        .write_enable(mask_low$write_enable)
    );
    skylux_core$capture$ingest$hdr$mask_high mask_high(
        .read_address(mask_high$read_address),
        .read_clock(mask_high$read_clock),
        .read_data(mask_high$read_data),
        .write_address(mask_high$write_address),
        .write_clock(mask_high$write_clock),
        .write_data(mask_high$write_data),
        .write_enable(mask_high$write_enable)
    );
    skylux_core$capture$ingest$hdr$pos pos(
        .d(pos$d),
        .q(pos$q),
        .clock(pos$clock)
    );
    skylux_core$capture$ingest$hdr$set_first set_first(
        .d(set_first$d),
        .q(set_first$q),
        .clock(set_first$clock)
    );
    skylux_core$capture$ingest$hdr$index index(
        .d(index$d),
        .q(index$q),
        .clock(index$clock)
    );
    
    // Update code
    always @(*) begin
        pos$clock = clock;
        set_first$clock = clock;
        index$clock = clock;
        pos$d = pos$q;
        set_first$d = set_first$q;
        index$d = index$q;
        mask_low$read_clock = clock;
        mask_low$write_clock = clock;
        mask_high$read_clock = clock;
        mask_high$write_clock = clock;
        next_pos = pos$q;
        if (take) begin
            next_pos = pos$q + 32'h1;
        end
        if (restart) begin
            next_pos = 32'h0;
            set_first$d = first_of_set;
            index$d = exposure_index;
        end
        pos$d = next_pos;
        mask_low$read_address = next_pos[(32'h0)+:(20)];
        mask_high$read_address = next_pos[(32'h0)+:(18)];
        luma = word[(32'h3)+:(27)];
        usable = ~word[32'h1f] & ~word[32'h1e] & (luma >= min_q11) & (luma <= max_q11);
        filled = 1'b0;
        if (~set_first$q) begin
            if (pos$q[32'h14]) begin
                filled = mask_high$read_data;
            end
            else begin
                filled = mask_low$read_data;
            end
        end
        mask_low$write_address = pos$q[(32'h0)+:(20)];
        mask_high$write_address = pos$q[(32'h0)+:(18)];
        mask_low$write_data = filled | usable;
        mask_high$write_data = filled | usable;
        mask_low$write_enable = take & ~pos$q[32'h14];
        mask_high$write_enable = take & pos$q[32'h14];
        map_word = (((word[(32'h1e)+:(2)]) & 32'hffffffff) << 32'h1e) | (((index$q) & 32'hffffffff) << 32'h1b) | ((luma) & 32'hffffffff);
        map_write = take & ~filled;
        map_settles = take & ~filled & usable;
    end
    
endmodule // skylux_core$capture$ingest$hdr


module skylux_core$capture$ingest$hdr$index(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$hdr$index


module skylux_core$capture$ingest$hdr$mask_high(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [17:0] read_address;
    input wire  read_clock;
    output reg  read_data;
    input wire  [17:0] write_address;
    input wire  write_clock;
    input wire  write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[0:0] mem[262143:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // skylux_core$capture$ingest$hdr$mask_high


module skylux_core$capture$ingest$hdr$mask_low(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [19:0] read_address;
    input wire  read_clock;
    output reg  read_data;
    input wire  [19:0] write_address;
    input wire  write_clock;
    input wire  write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[0:0] mem[1048575:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // skylux_core$capture$ingest$hdr$mask_low


module skylux_core$capture$ingest$hdr$pos(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$hdr$pos


module skylux_core$capture$ingest$hdr$set_first(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$hdr$set_first


module skylux_core$capture$ingest$hdr_frame(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$hdr_frame


module skylux_core$capture$ingest$high_water(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$high_water


module skylux_core$capture$ingest$info(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$info


module skylux_core$capture$ingest$last_high_water(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$last_high_water


module skylux_core$capture$ingest$last_lines(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$last_lines


module skylux_core$capture$ingest$last_pixels(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$last_pixels


module skylux_core$capture$ingest$new_set_pending(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$new_set_pending


module skylux_core$capture$ingest$pending_exposure(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$pending_exposure


module skylux_core$capture$ingest$pending_frame_number(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$pending_frame_number


module skylux_core$capture$ingest$pending_timestamp(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$pending_timestamp


module skylux_core$capture$ingest$set_ordinal(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$set_ordinal


module skylux_core$capture$ingest$set_sum(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$set_sum


module skylux_core$capture$ingest$since_heartbeat(d,q,clock);
    
    // Module arguments
    input wire  [10:0] d;
    output reg  [10:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 11'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$since_heartbeat


module skylux_core$capture$ingest$state(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Enums
    localparam IngestState$Idle = 0;
    localparam IngestState$Frame = 1;
    localparam IngestState$Ended = 2;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$state


module skylux_core$capture$ingest$timestamp(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$timestamp


module skylux_core$capture$ingest$words(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$ingest$words


module skylux_core$capture$sun(clock,word_valid,word,frame_start,armed,groups_per_line,threshold_q14,x_min,x_max,y_min,y_max,sun_count,over_count,sum_l,sum_xl,sum_yl,max_l,min_x,max_x,min_y,max_y,armed_frames);
    
    // Module arguments
    input wire  clock;
    input wire  word_valid;
    input wire  [31:0] word;
    input wire  frame_start;
    input wire  armed;
    input wire  [10:0] groups_per_line;
    input wire  [29:0] threshold_q14;
    input wire  [10:0] x_min;
    input wire  [10:0] x_max;
    input wire  [10:0] y_min;
    input wire  [10:0] y_max;
    output reg  [20:0] sun_count;
    output reg  [20:0] over_count;
    output reg  [63:0] sum_l;
    output reg  [63:0] sum_xl;
    output reg  [63:0] sum_yl;
    output reg  [29:0] max_l;
    output reg  [10:0] min_x;
    output reg  [10:0] max_x;
    output reg  [10:0] min_y;
    output reg  [10:0] max_y;
    output reg  [15:0] armed_frames;
    
    // Stub signals
    reg  position$clock;
    reg  position$word_valid;
    reg  position$frame_start;
    reg  position$armed;
    reg  [10:0] position$groups_per_line;
    wire  [10:0] position$pos_x;
    wire  [10:0] position$pos_y;
    wire  position$armed_now;
    reg  s1_first$d;
    wire  s1_first$q;
    reg  s1_first$clock;
    reg  s1_counts$d;
    wire  s1_counts$q;
    reg  s1_counts$clock;
    reg  s1_over$d;
    wire  s1_over$q;
    reg  s1_over$clock;
    reg  [29:0] s1_l$d;
    wire  [29:0] s1_l$q;
    reg  s1_l$clock;
    reg  [10:0] s1_x$d;
    wire  [10:0] s1_x$q;
    reg  s1_x$clock;
    reg  [10:0] s1_y$d;
    wire  [10:0] s1_y$q;
    reg  s1_y$clock;
    reg  s2_first$d;
    wire  s2_first$q;
    reg  s2_first$clock;
    reg  s2_counts$d;
    wire  s2_counts$q;
    reg  s2_counts$clock;
    reg  s2_over$d;
    wire  s2_over$q;
    reg  s2_over$clock;
    reg  [29:0] s2_l$d;
    wire  [29:0] s2_l$q;
    reg  s2_l$clock;
    reg  [10:0] s2_x$d;
    wire  [10:0] s2_x$q;
    reg  s2_x$clock;
    reg  [10:0] s2_y$d;
    wire  [10:0] s2_y$q;
    reg  s2_y$clock;
    reg  [31:0] s2_xl_high$d;
    wire  [31:0] s2_xl_high$q;
    reg  s2_xl_high$clock;
    reg  [31:0] s2_xl_low$d;
    wire  [31:0] s2_xl_low$q;
    reg  s2_xl_low$clock;
    reg  [31:0] s2_yl_high$d;
    wire  [31:0] s2_yl_high$q;
    reg  s2_yl_high$clock;
    reg  [31:0] s2_yl_low$d;
    wire  [31:0] s2_yl_low$q;
    reg  s2_yl_low$clock;
    reg  [20:0] acc_count$d;
    wire  [20:0] acc_count$q;
    reg  acc_count$clock;
    reg  [20:0] acc_over$d;
    wire  [20:0] acc_over$q;
    reg  acc_over$clock;
    reg  [63:0] acc_l$d;
    wire  [63:0] acc_l$q;
    reg  acc_l$clock;
    reg  [63:0] acc_xl$d;
    wire  [63:0] acc_xl$q;
    reg  acc_xl$clock;
    reg  [63:0] acc_yl$d;
    wire  [63:0] acc_yl$q;
    reg  acc_yl$clock;
    reg  [29:0] acc_max$d;
    wire  [29:0] acc_max$q;
    reg  acc_max$clock;
    reg  [10:0] acc_min_x$d;
    wire  [10:0] acc_min_x$q;
    reg  acc_min_x$clock;
    reg  [10:0] acc_max_x$d;
    wire  [10:0] acc_max_x$q;
    reg  acc_max_x$clock;
    reg  [10:0] acc_min_y$d;
    wire  [10:0] acc_min_y$q;
    reg  acc_min_y$clock;
    reg  [10:0] acc_max_y$d;
    wire  [10:0] acc_max_y$q;
    reg  acc_max_y$clock;
    reg  [15:0] acc_frames$d;
    wire  [15:0] acc_frames$q;
    reg  acc_frames$clock;
    
    // Local signals
    reg  [29:0] luma;
    reg  [63:0] xl;
    reg  [63:0] yl;
    reg  [20:0] base_count;
    reg  [20:0] base_over;
    reg  [63:0] base_l;
    reg  [63:0] base_xl;
    reg  [63:0] base_yl;
    reg  [29:0] base_max;
    
    // Sub module instances
    skylux_core$capture$sun$position position(
        .clock(position$clock),
        .word_valid(position$word_valid),
        .frame_start(position$frame_start),
        .armed(position$armed),
        .groups_per_line(position$groups_per_line),
        .pos_x(position$pos_x),
        .pos_y(position$pos_y),
        .armed_now(position$armed_now)
    );
    skylux_core$capture$sun$s1_first s1_first(
        .d(s1_first$d),
        .q(s1_first$q),
        .clock(s1_first$clock)
    );
    skylux_core$capture$sun$s1_counts s1_counts(
        .d(s1_counts$d),
        .q(s1_counts$q),
        .clock(s1_counts$clock)
    );
    skylux_core$capture$sun$s1_over s1_over(
        .d(s1_over$d),
        .q(s1_over$q),
        .clock(s1_over$clock)
    );
    skylux_core$capture$sun$s1_l s1_l(
        .d(s1_l$d),
        .q(s1_l$q),
        .clock(s1_l$clock)
    );
    skylux_core$capture$sun$s1_x s1_x(
        .d(s1_x$d),
        .q(s1_x$q),
        .clock(s1_x$clock)
    );
    skylux_core$capture$sun$s1_y s1_y(
        .d(s1_y$d),
        .q(s1_y$q),
        .clock(s1_y$clock)
    );
    skylux_core$capture$sun$s2_first s2_first(
        .d(s2_first$d),
        .q(s2_first$q),
        .clock(s2_first$clock)
    );
    skylux_core$capture$sun$s2_counts s2_counts(
        .d(s2_counts$d),
        .q(s2_counts$q),
        .clock(s2_counts$clock)
    );
    skylux_core$capture$sun$s2_over s2_over(
        .d(s2_over$d),
        .q(s2_over$q),
        .clock(s2_over$clock)
    );
    skylux_core$capture$sun$s2_l s2_l(
        .d(s2_l$d),
        .q(s2_l$q),
        .clock(s2_l$clock)
    );
    skylux_core$capture$sun$s2_x s2_x(
        .d(s2_x$d),
        .q(s2_x$q),
        .clock(s2_x$clock)
    );
    skylux_core$capture$sun$s2_y s2_y(
        .d(s2_y$d),
        .q(s2_y$q),
        .clock(s2_y$clock)
    );
    skylux_core$capture$sun$s2_xl_high s2_xl_high(
        .d(s2_xl_high$d),
        .q(s2_xl_high$q),
        .clock(s2_xl_high$clock)
    );
    skylux_core$capture$sun$s2_xl_low s2_xl_low(
        .d(s2_xl_low$d),
        .q(s2_xl_low$q),
        .clock(s2_xl_low$clock)
    );
    skylux_core$capture$sun$s2_yl_high s2_yl_high(
        .d(s2_yl_high$d),
        .q(s2_yl_high$q),
        .clock(s2_yl_high$clock)
    );
    skylux_core$capture$sun$s2_yl_low s2_yl_low(
        .d(s2_yl_low$d),
        .q(s2_yl_low$q),
        .clock(s2_yl_low$clock)
    );
    skylux_core$capture$sun$acc_count acc_count(
        .d(acc_count$d),
        .q(acc_count$q),
        .clock(acc_count$clock)
    );
    skylux_core$capture$sun$acc_over acc_over(
        .d(acc_over$d),
        .q(acc_over$q),
        .clock(acc_over$clock)
    );
    skylux_core$capture$sun$acc_l acc_l(
        .d(acc_l$d),
        .q(acc_l$q),
        .clock(acc_l$clock)
    );
    skylux_core$capture$sun$acc_xl acc_xl(
        .d(acc_xl$d),
        .q(acc_xl$q),
        .clock(acc_xl$clock)
    );
    skylux_core$capture$sun$acc_yl acc_yl(
        .d(acc_yl$d),
        .q(acc_yl$q),
        .clock(acc_yl$clock)
    );
    skylux_core$capture$sun$acc_max acc_max(
        .d(acc_max$d),
        .q(acc_max$q),
        .clock(acc_max$clock)
    );
    skylux_core$capture$sun$acc_min_x acc_min_x(
        .d(acc_min_x$d),
        .q(acc_min_x$q),
        .clock(acc_min_x$clock)
    );
    skylux_core$capture$sun$acc_max_x acc_max_x(
        .d(acc_max_x$d),
        .q(acc_max_x$q),
        .clock(acc_max_x$clock)
    );
    skylux_core$capture$sun$acc_min_y acc_min_y(
        .d(acc_min_y$d),
        .q(acc_min_y$q),
        .clock(acc_min_y$clock)
    );
    skylux_core$capture$sun$acc_max_y acc_max_y(
        .d(acc_max_y$d),
        .q(acc_max_y$q),
        .clock(acc_max_y$clock)
    );
    skylux_core$capture$sun$acc_frames acc_frames(
        .d(acc_frames$d),
        .q(acc_frames$q),
        .clock(acc_frames$clock)
    );
    
    // Update code
    always @(*) begin
        s1_first$clock = clock;
        s1_counts$clock = clock;
        s1_over$clock = clock;
        s1_l$clock = clock;
        s1_x$clock = clock;
        s1_y$clock = clock;
        s2_first$clock = clock;
        s2_counts$clock = clock;
        s2_over$clock = clock;
        s2_l$clock = clock;
        s2_x$clock = clock;
        s2_y$clock = clock;
        s2_xl_high$clock = clock;
        s2_xl_low$clock = clock;
        s2_yl_high$clock = clock;
        s2_yl_low$clock = clock;
        acc_count$clock = clock;
        acc_over$clock = clock;
        acc_l$clock = clock;
        acc_xl$clock = clock;
        acc_yl$clock = clock;
        acc_max$clock = clock;
        acc_min_x$clock = clock;
        acc_max_x$clock = clock;
        acc_min_y$clock = clock;
        acc_max_y$clock = clock;
        acc_frames$clock = clock;
        s1_first$d = s1_first$q;
        s1_counts$d = s1_counts$q;
        s1_over$d = s1_over$q;
        s1_l$d = s1_l$q;
        s1_x$d = s1_x$q;
        s1_y$d = s1_y$q;
        s2_first$d = s2_first$q;
        s2_counts$d = s2_counts$q;
        s2_over$d = s2_over$q;
        s2_l$d = s2_l$q;
        s2_x$d = s2_x$q;
        s2_y$d = s2_y$q;
        s2_xl_high$d = s2_xl_high$q;
        s2_xl_low$d = s2_xl_low$q;
        s2_yl_high$d = s2_yl_high$q;
        s2_yl_low$d = s2_yl_low$q;
        acc_count$d = acc_count$q;
        acc_over$d = acc_over$q;
        acc_l$d = acc_l$q;
        acc_xl$d = acc_xl$q;
        acc_yl$d = acc_yl$q;
        acc_max$d = acc_max$q;
        acc_min_x$d = acc_min_x$q;
        acc_max_x$d = acc_max_x$q;
        acc_min_y$d = acc_min_y$q;
        acc_max_y$d = acc_max_y$q;
        acc_frames$d = acc_frames$q;
        position$clock = clock;
        position$word_valid = word_valid;
        position$frame_start = frame_start;
        position$armed = armed;
        position$groups_per_line = groups_per_line;
        luma = word[(32'h0)+:(30)];
        s1_first$d = word_valid & frame_start & armed;
        s1_counts$d = word_valid & position$armed_now & (position$pos_x >= x_min) & (position$pos_x <= x_max) & (position$pos_y >= y_min) & (position$pos_y <= y_max) & (luma >= threshold_q14);
        s1_over$d = word[32'h1f];
        s1_l$d = luma;
        s1_x$d = position$pos_x;
        s1_y$d = position$pos_y;
        s2_first$d = s1_first$q;
        s2_counts$d = s1_counts$q;
        s2_over$d = s1_over$q;
        s2_l$d = s1_l$q;
        s2_x$d = s1_x$q;
        s2_y$d = s1_y$q;
        s2_xl_high$d = ((s1_x$q) & 16'hffff) * ((s1_l$q[(32'hf)+:(15)]) & 16'hffff);
        s2_xl_low$d = ((s1_x$q) & 16'hffff) * ((s1_l$q[(32'h0)+:(15)]) & 16'hffff);
        s2_yl_high$d = ((s1_y$q) & 16'hffff) * ((s1_l$q[(32'hf)+:(15)]) & 16'hffff);
        s2_yl_low$d = ((s1_y$q) & 16'hffff) * ((s1_l$q[(32'h0)+:(15)]) & 16'hffff);
        xl = (((s2_xl_high$q) & 64'hffffffffffffffff) << 32'hf) + ((s2_xl_low$q) & 64'hffffffffffffffff);
        yl = (((s2_yl_high$q) & 64'hffffffffffffffff) << 32'hf) + ((s2_yl_low$q) & 64'hffffffffffffffff);
        base_count = acc_count$q;
        base_over = acc_over$q;
        base_l = acc_l$q;
        base_xl = acc_xl$q;
        base_yl = acc_yl$q;
        base_max = acc_max$q;
        if (s2_first$q) begin
            base_count = 32'h0;
            base_over = 32'h0;
            base_l = 32'h0;
            base_xl = 32'h0;
            base_yl = 32'h0;
            base_max = 32'h0;
            acc_min_x$d = 32'h0;
            acc_max_x$d = 32'h0;
            acc_min_y$d = 32'h0;
            acc_max_y$d = 32'h0;
            acc_frames$d = acc_frames$q + 32'h1;
        end
        acc_count$d = base_count;
        acc_over$d = base_over;
        acc_l$d = base_l;
        acc_xl$d = base_xl;
        acc_yl$d = base_yl;
        acc_max$d = base_max;
        if (s2_counts$q) begin
            acc_count$d = base_count + 32'h1;
            if (s2_over$q) begin
                acc_over$d = base_over + 32'h1;
            end
            acc_l$d = base_l + ((s2_l$q) & 64'hffffffffffffffff);
            acc_xl$d = base_xl + xl;
            acc_yl$d = base_yl + yl;
            if (s2_l$q > base_max) begin
                acc_max$d = s2_l$q;
            end
            if (base_count == 32'h0) begin
                acc_min_x$d = s2_x$q;
                acc_max_x$d = s2_x$q;
                acc_min_y$d = s2_y$q;
                acc_max_y$d = s2_y$q;
            end
            else begin
                if (s2_x$q < acc_min_x$q) begin
                    acc_min_x$d = s2_x$q;
                end
                if (s2_x$q > acc_max_x$q) begin
                    acc_max_x$d = s2_x$q;
                end
                if (s2_y$q < acc_min_y$q) begin
                    acc_min_y$d = s2_y$q;
                end
                if (s2_y$q > acc_max_y$q) begin
                    acc_max_y$d = s2_y$q;
                end
            end
        end
        sun_count = acc_count$q;
        over_count = acc_over$q;
        sum_l = acc_l$q;
        sum_xl = acc_xl$q;
        sum_yl = acc_yl$q;
        max_l = acc_max$q;
        min_x = acc_min_x$q;
        max_x = acc_max_x$q;
        min_y = acc_min_y$q;
        max_y = acc_max_y$q;
        armed_frames = acc_frames$q;
    end
    
endmodule // skylux_core$capture$sun


module skylux_core$capture$sun$acc_count(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$sun$acc_count


module skylux_core$capture$sun$acc_frames(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$sun$acc_frames


module skylux_core$capture$sun$acc_l(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$sun$acc_l


module skylux_core$capture$sun$acc_max(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$sun$acc_max


module skylux_core$capture$sun$acc_max_x(d,q,clock);
    
    // Module arguments
    input wire  [10:0] d;
    output reg  [10:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 11'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$sun$acc_max_x


module skylux_core$capture$sun$acc_max_y(d,q,clock);
    
    // Module arguments
    input wire  [10:0] d;
    output reg  [10:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 11'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$sun$acc_max_y


module skylux_core$capture$sun$acc_min_x(d,q,clock);
    
    // Module arguments
    input wire  [10:0] d;
    output reg  [10:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 11'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$sun$acc_min_x


module skylux_core$capture$sun$acc_min_y(d,q,clock);
    
    // Module arguments
    input wire  [10:0] d;
    output reg  [10:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 11'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$sun$acc_min_y


module skylux_core$capture$sun$acc_over(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$sun$acc_over


module skylux_core$capture$sun$acc_xl(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$sun$acc_xl


module skylux_core$capture$sun$acc_yl(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$sun$acc_yl


module skylux_core$capture$sun$position(clock,word_valid,frame_start,armed,groups_per_line,pos_x,pos_y,armed_now);
    
    // Module arguments
    input wire  clock;
    input wire  word_valid;
    input wire  frame_start;
    input wire  armed;
    input wire  [10:0] groups_per_line;
    output reg  [10:0] pos_x;
    output reg  [10:0] pos_y;
    output reg  armed_now;
    
    // Stub signals
    reg  [10:0] next_x$d;
    wire  [10:0] next_x$q;
    reg  next_x$clock;
    reg  [10:0] next_y$d;
    wire  [10:0] next_y$q;
    reg  next_y$clock;
    reg  frame_armed$d;
    wire  frame_armed$q;
    reg  frame_armed$clock;
    
    // Sub module instances
    skylux_core$capture$sun$position$next_x next_x(
        .d(next_x$d),
        .q(next_x$q),
        .clock(next_x$clock)
    );
    skylux_core$capture$sun$position$next_y next_y(
        .d(next_y$d),
        .q(next_y$q),
        .clock(next_y$clock)
    );
    skylux_core$capture$sun$position$frame_armed frame_armed(
        .d(frame_armed$d),
        .q(frame_armed$q),
        .clock(frame_armed$clock)
    );
    
    // Update code
    always @(*) begin
        next_x$clock = clock;
        next_y$clock = clock;
        frame_armed$clock = clock;
        next_x$d = next_x$q;
        next_y$d = next_y$q;
        frame_armed$d = frame_armed$q;
        pos_x = next_x$q;
        pos_y = next_y$q;
        armed_now = frame_armed$q;
        if (word_valid & frame_start) begin
            pos_x = 32'h0;
            pos_y = 32'h0;
            armed_now = armed;
            frame_armed$d = armed;
        end
        if (word_valid) begin
            next_x$d = pos_x + 32'h1;
            next_y$d = pos_y;
            if ((pos_x + 32'h1) >= groups_per_line) begin
                next_x$d = 32'h0;
                next_y$d = pos_y + 32'h1;
            end
        end
    end
    
endmodule // skylux_core$capture$sun$position


module skylux_core$capture$sun$position$frame_armed(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$sun$position$frame_armed


module skylux_core$capture$sun$position$next_x(d,q,clock);
    
    // Module arguments
    input wire  [10:0] d;
    output reg  [10:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 11'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$sun$position$next_x


module skylux_core$capture$sun$position$next_y(d,q,clock);
    
    // Module arguments
    input wire  [10:0] d;
    output reg  [10:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 11'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$sun$position$next_y


module skylux_core$capture$sun$s1_counts(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$sun$s1_counts


module skylux_core$capture$sun$s1_first(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$sun$s1_first


module skylux_core$capture$sun$s1_l(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$sun$s1_l


module skylux_core$capture$sun$s1_over(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$sun$s1_over


module skylux_core$capture$sun$s1_x(d,q,clock);
    
    // Module arguments
    input wire  [10:0] d;
    output reg  [10:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 11'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$sun$s1_x


module skylux_core$capture$sun$s1_y(d,q,clock);
    
    // Module arguments
    input wire  [10:0] d;
    output reg  [10:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 11'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$sun$s1_y


module skylux_core$capture$sun$s2_counts(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$sun$s2_counts


module skylux_core$capture$sun$s2_first(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$sun$s2_first


module skylux_core$capture$sun$s2_l(d,q,clock);
    
    // Module arguments
    input wire  [29:0] d;
    output reg  [29:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 30'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$sun$s2_l


module skylux_core$capture$sun$s2_over(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$sun$s2_over


module skylux_core$capture$sun$s2_x(d,q,clock);
    
    // Module arguments
    input wire  [10:0] d;
    output reg  [10:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 11'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$sun$s2_x


module skylux_core$capture$sun$s2_xl_high(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$sun$s2_xl_high


module skylux_core$capture$sun$s2_xl_low(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$sun$s2_xl_low


module skylux_core$capture$sun$s2_y(d,q,clock);
    
    // Module arguments
    input wire  [10:0] d;
    output reg  [10:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 11'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$sun$s2_y


module skylux_core$capture$sun$s2_yl_high(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$sun$s2_yl_high


module skylux_core$capture$sun$s2_yl_low(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$sun$s2_yl_low


module skylux_core$capture$writer(clock,restart,window_base,window_size,slot_stride,slots,bus_timeout,beat_push,beat_data,beat_byteenable,frame_open,frame_ended,desc_frame_number,desc_timestamp,desc_info,desc_geometry,desc_words,desc_checksum,writer_idle,frame_closed,beat_room,dma_status_busy,dma_status_slot,dma_status_frame_done_set,dma_status_out_of_window_set,dma_status_bus_timeout_set,dma_frames_written_count,avm_address,avm_burstcount,avm_write,avm_writedata,avm_byteenable,avm_waitrequest);
    
    // Module arguments
    input wire  clock;
    input wire  restart;
    input wire  [31:0] window_base;
    input wire  [31:0] window_size;
    input wire  [31:0] slot_stride;
    input wire  [7:0] slots;
    input wire  [23:0] bus_timeout;
    input wire  beat_push;
    input wire  [63:0] beat_data;
    input wire  [7:0] beat_byteenable;
    input wire  frame_open;
    input wire  frame_ended;
    input wire  [31:0] desc_frame_number;
    input wire  [63:0] desc_timestamp;
    input wire  [31:0] desc_info;
    input wire  [31:0] desc_geometry;
    input wire  [31:0] desc_words;
    input wire  [31:0] desc_checksum;
    output reg  writer_idle;
    output reg  frame_closed;
    output reg  beat_room;
    output reg  dma_status_busy;
    output reg  [7:0] dma_status_slot;
    output reg  dma_status_frame_done_set;
    output reg  dma_status_out_of_window_set;
    output reg  dma_status_bus_timeout_set;
    output reg  [31:0] dma_frames_written_count;
    output reg  [31:0] avm_address;
    output reg  [7:0] avm_burstcount;
    output reg  avm_write;
    output reg  [63:0] avm_writedata;
    output reg  [7:0] avm_byteenable;
    input wire  avm_waitrequest;
    
    // Constant declarations
    localparam  format_id = 32'h31464b53;
    localparam  max_burst = 8'h80;
    localparam  descriptor_beats = 8'h4;
    localparam  truncated_flag = 32'h400000;
    localparam  bus_timeout_flag = 32'h800000;
    
    // Enums
    localparam WriterState$Idle = 0;
    localparam WriterState$Plan = 1;
    localparam WriterState$Burst = 2;
    localparam WriterState$Drain = 3;
    localparam WriterState$Descriptor = 4;
    localparam WriterState$Close = 5;
    
    // Stub signals
    reg  beats$clock;
    reg  beats$read;
    wire  [63:0] beats$data_out;
    wire  beats$empty;
    wire  beats$almost_empty;
    wire  beats$underflow;
    reg  beats$write;
    reg  [63:0] beats$data_in;
    wire  beats$full;
    wire  beats$almost_full;
    wire  beats$overflow;
    reg  enables$clock;
    reg  enables$read;
    wire  [7:0] enables$data_out;
    wire  enables$empty;
    wire  enables$almost_empty;
    wire  enables$underflow;
    reg  enables$write;
    reg  [7:0] enables$data_in;
    wire  enables$full;
    wire  enables$almost_full;
    wire  enables$overflow;
    reg  [8:0] queued$d;
    wire  [8:0] queued$q;
    reg  queued$clock;
    reg  [2:0] state$d;
    wire  [2:0] state$q;
    reg  state$clock;
    reg  [7:0] slot$d;
    wire  [7:0] slot$q;
    reg  slot$clock;
    reg  [31:0] slot_offset$d;
    wire  [31:0] slot_offset$q;
    reg  slot_offset$clock;
    reg  restart_pending$d;
    wire  restart_pending$q;
    reg  restart_pending$clock;
    reg  slot_ok$d;
    wire  slot_ok$q;
    reg  slot_ok$clock;
    reg  [31:0] slot_addr$d;
    wire  [31:0] slot_addr$q;
    reg  slot_addr$clock;
    reg  [32:0] slot_end$d;
    wire  [32:0] slot_end$q;
    reg  slot_end$clock;
    reg  [31:0] addr$d;
    wire  [31:0] addr$q;
    reg  addr$clock;
    reg  [7:0] burst_len$d;
    wire  [7:0] burst_len$q;
    reg  burst_len$clock;
    reg  [7:0] beats_left$d;
    wire  [7:0] beats_left$q;
    reg  beats_left$clock;
    reg  [1:0] desc_beat$d;
    wire  [1:0] desc_beat$q;
    reg  desc_beat$clock;
    reg  [31:0] flags$d;
    wire  [31:0] flags$q;
    reg  flags$clock;
    reg  [23:0] stall$d;
    wire  [23:0] stall$q;
    reg  stall$clock;
    reg  timed_out$d;
    wire  timed_out$q;
    reg  timed_out$clock;
    reg  [31:0] frames_written$d;
    wire  [31:0] frames_written$q;
    reg  frames_written$clock;
    
    // Local signals
    reg  pop;
    reg  [32:0] base_wide;
    reg  [32:0] size_wide;
    reg  [32:0] stride_wide;
    reg  [32:0] slot_end_in_window;
    reg  [32:0] window_end;
    reg  slot_fits;
    reg  [7:0] plan_len;
    reg  plan_go;
    reg  [32:0] room_beats;
    reg  stalled;
    reg  accepted;
    reg  [7:0] next_slot;
    reg  advance;
    reg  [63:0] descriptor_beat;
    
    // Sub module instances
    skylux_core$capture$writer$beats beats(
        .clock(beats$clock),
        .read(beats$read),
        .data_out(beats$data_out),
        .empty(beats$empty),
        .almost_empty(beats$almost_empty),
        .underflow(beats$underflow),
        .write(beats$write),
        .data_in(beats$data_in),
        .full(beats$full),
        .almost_full(beats$almost_full),
        .overflow(beats$overflow)
    );
    skylux_core$capture$writer$enables enables(
        .clock(enables$clock),
        .read(enables$read),
        .data_out(enables$data_out),
        .empty(enables$empty),
        .almost_empty(enables$almost_empty),
        .underflow(enables$underflow),
        .write(enables$write),
        .data_in(enables$data_in),
        .full(enables$full),
        .almost_full(enables$almost_full),
        .overflow(enables$overflow)
    );
    skylux_core$capture$writer$queued queued(
        .d(queued$d),
        .q(queued$q),
        .clock(queued$clock)
    );
    skylux_core$capture$writer$state state(
        .d(state$d),
        .q(state$q),
        .clock(state$clock)
    );
    skylux_core$capture$writer$slot slot(
        .d(slot$d),
        .q(slot$q),
        .clock(slot$clock)
    );
    skylux_core$capture$writer$slot_offset slot_offset(
        .d(slot_offset$d),
        .q(slot_offset$q),
        .clock(slot_offset$clock)
    );
    skylux_core$capture$writer$restart_pending restart_pending(
        .d(restart_pending$d),
        .q(restart_pending$q),
        .clock(restart_pending$clock)
    );
    skylux_core$capture$writer$slot_ok slot_ok(
        .d(slot_ok$d),
        .q(slot_ok$q),
        .clock(slot_ok$clock)
    );
    skylux_core$capture$writer$slot_addr slot_addr(
        .d(slot_addr$d),
        .q(slot_addr$q),
        .clock(slot_addr$clock)
    );
    skylux_core$capture$writer$slot_end slot_end(
        .d(slot_end$d),
        .q(slot_end$q),
        .clock(slot_end$clock)
    );
    skylux_core$capture$writer$addr addr(
        .d(addr$d),
        .q(addr$q),
        .clock(addr$clock)
    );
    skylux_core$capture$writer$burst_len burst_len(
        .d(burst_len$d),
        .q(burst_len$q),
        .clock(burst_len$clock)
    );
    skylux_core$capture$writer$beats_left beats_left(
        .d(beats_left$d),
        .q(beats_left$q),
        .clock(beats_left$clock)
    );
    skylux_core$capture$writer$desc_beat desc_beat(
        .d(desc_beat$d),
        .q(desc_beat$q),
        .clock(desc_beat$clock)
    );
    skylux_core$capture$writer$flags flags(
        .d(flags$d),
        .q(flags$q),
        .clock(flags$clock)
    );
    skylux_core$capture$writer$stall stall(
        .d(stall$d),
        .q(stall$q),
        .clock(stall$clock)
    );
    skylux_core$capture$writer$timed_out timed_out(
        .d(timed_out$d),
        .q(timed_out$q),
        .clock(timed_out$clock)
    );
    skylux_core$capture$writer$frames_written frames_written(
        .d(frames_written$d),
        .q(frames_written$q),
        .clock(frames_written$clock)
    );
    
    // Update code
    always @(*) begin
        queued$clock = clock;
        state$clock = clock;
        slot$clock = clock;
        slot_offset$clock = clock;
        restart_pending$clock = clock;
        slot_ok$clock = clock;
        slot_addr$clock = clock;
        slot_end$clock = clock;
        addr$clock = clock;
        burst_len$clock = clock;
        beats_left$clock = clock;
        desc_beat$clock = clock;
        flags$clock = clock;
        stall$clock = clock;
        timed_out$clock = clock;
        frames_written$clock = clock;
        queued$d = queued$q;
        state$d = state$q;
        slot$d = slot$q;
        slot_offset$d = slot_offset$q;
        restart_pending$d = restart_pending$q;
        slot_ok$d = slot_ok$q;
        slot_addr$d = slot_addr$q;
        slot_end$d = slot_end$q;
        addr$d = addr$q;
        burst_len$d = burst_len$q;
        beats_left$d = beats_left$q;
        desc_beat$d = desc_beat$q;
        flags$d = flags$q;
        stall$d = stall$q;
        timed_out$d = timed_out$q;
        frames_written$d = frames_written$q;
        beats$clock = clock;
        enables$clock = clock;
        beats$write = beat_push;
        beats$data_in = beat_data;
        enables$write = beat_push;
        enables$data_in = beat_byteenable;
        pop = 1'b0;
        beat_room = queued$q < 32'hfe;
        base_wide = 32'h0;
        size_wide = 32'h0;
        stride_wide = 32'h0;
        slot_end_in_window = 32'h0;
        window_end = 32'h0;
        slot_fits = 1'b0;
        plan_len = max_burst;
        plan_go = 1'b0;
        room_beats = 32'h0;
        descriptor_beat = 32'h0;
        avm_address = addr$q;
        avm_burstcount = burst_len$q;
        avm_write = 1'b0;
        avm_writedata = 32'h0;
        avm_byteenable = 32'hff;
        stalled = 1'b0;
        accepted = 1'b0;
        writer_idle = 1'b0;
        frame_closed = 1'b0;
        dma_status_frame_done_set = 1'b0;
        dma_status_out_of_window_set = 1'b0;
        dma_status_bus_timeout_set = 1'b0;
        advance = 1'b0;
        next_slot = slot$q + 32'h1;
        if (restart) begin
            restart_pending$d = 1'b1;
        end
        case (state$q)
            WriterState$Idle:
                begin
                    writer_idle = 1'b1;
                    if (frame_open) begin
                        base_wide = ((window_base) & 33'h1ffffffff);
                        size_wide = ((window_size) & 33'h1ffffffff);
                        stride_wide = ((slot_stride) & 33'h1ffffffff);
                        slot_end_in_window = ((slot_offset$q) & 33'h1ffffffff) + stride_wide;
                        window_end = base_wide + size_wide;
                        slot_fits = ~|window_base[(32'h0)+:(3)] & ~|slot_stride[(32'h0)+:(3)] & (slot_stride >= 32'h48) & (slot_end_in_window <= size_wide) & ~(window_end[32'h20] & |window_end[(32'h0)+:(32)]);
                        flags$d = 32'h0;
                        stall$d = 32'h0;
                        timed_out$d = 1'b0;
                        slot_addr$d = window_base + slot_offset$q;
                        addr$d = window_base + slot_offset$q + 32'h40;
                        slot_end$d = base_wide + slot_end_in_window;
                        slot_ok$d = slot_fits;
                        if (slot_fits) begin
                            state$d = WriterState$Plan;
                        end
                        else begin
                            dma_status_out_of_window_set = 1'b1;
                            state$d = WriterState$Drain;
                        end
                    end
                    else if (restart_pending$q) begin
                        restart_pending$d = 1'b0;
                        slot$d = 32'h0;
                        slot_offset$d = 32'h0;
                    end
                end
            WriterState$Plan:
                begin
                    if (queued$q < 32'h80) begin
                        plan_len = queued$q[(32'h0)+:(8)];
                    end
                    plan_go = (queued$q >= 32'h80) | (frame_ended & |queued$q);
                    if (plan_go) begin
                        room_beats = (slot_end$q - ((addr$q) & 33'h1ffffffff)) >> 32'h3;
                        if (room_beats >= ((plan_len) & 33'h1ffffffff)) begin
                            burst_len$d = plan_len;
                            beats_left$d = plan_len;
                            state$d = WriterState$Burst;
                        end
                        else if (|room_beats) begin
                            burst_len$d = room_beats[(32'h0)+:(8)];
                            beats_left$d = room_beats[(32'h0)+:(8)];
                            flags$d = flags$q | truncated_flag;
                            dma_status_out_of_window_set = 1'b1;
                            state$d = WriterState$Burst;
                        end
                        else begin
                            flags$d = flags$q | truncated_flag;
                            dma_status_out_of_window_set = 1'b1;
                            state$d = WriterState$Drain;
                        end
                    end
                    else if (frame_ended) begin
                        desc_beat$d = 32'h0;
                        addr$d = slot_addr$q;
                        burst_len$d = descriptor_beats;
                        state$d = WriterState$Descriptor;
                    end
                end
            WriterState$Burst:
                begin
                    avm_write = 1'b1;
                    avm_writedata = beats$data_out;
                    avm_byteenable = enables$data_out;
                    if (avm_waitrequest) begin
                        stalled = 1'b1;
                    end
                    else begin
                        accepted = 1'b1;
                        pop = 1'b1;
                        beats_left$d = beats_left$q - 32'h1;
                        if (beats_left$q == 32'h1) begin
                            addr$d = addr$q + (((burst_len$q) & 32'hffffffff) << 32'h3);
                            state$d = WriterState$Plan;
                        end
                    end
                end
            WriterState$Drain:
                begin
                    pop = ~beats$empty;
                    if (frame_ended & ~|queued$q) begin
                        if (slot_ok$q) begin
                            desc_beat$d = 32'h0;
                            addr$d = slot_addr$q;
                            burst_len$d = descriptor_beats;
                            state$d = WriterState$Descriptor;
                        end
                        else begin
                            state$d = WriterState$Close;
                        end
                    end
                end
            WriterState$Descriptor:
                begin
                    descriptor_beat = ((format_id) & 64'hffffffffffffffff) | (((desc_frame_number) & 64'hffffffffffffffff) << 32'h20);
                    if (desc_beat$q == 32'h1) begin
                        descriptor_beat = desc_timestamp;
                    end
                    if (desc_beat$q == 32'h2) begin
                        descriptor_beat = ((desc_info | flags$q) & 64'hffffffffffffffff) | (((desc_geometry) & 64'hffffffffffffffff) << 32'h20);
                    end
                    if (desc_beat$q == 32'h3) begin
                        descriptor_beat = ((desc_words) & 64'hffffffffffffffff) | (((desc_checksum) & 64'hffffffffffffffff) << 32'h20);
                    end
                    avm_write = 1'b1;
                    avm_writedata = descriptor_beat;
                    if (avm_waitrequest) begin
                        stalled = 1'b1;
                    end
                    else begin
                        accepted = 1'b1;
                        desc_beat$d = desc_beat$q + 32'h1;
                        if (desc_beat$q == 32'h3) begin
                            state$d = WriterState$Close;
                        end
                    end
                end
            WriterState$Close:
                begin
                    frame_closed = 1'b1;
                    state$d = WriterState$Idle;
                    if (slot_ok$q) begin
                        dma_status_frame_done_set = 1'b1;
                        frames_written$d = frames_written$q + 32'h1;
                        advance = 1'b1;
                    end
                    if (restart_pending$q) begin
                        restart_pending$d = 1'b0;
                        slot$d = 32'h0;
                        slot_offset$d = 32'h0;
                    end
                    else if (advance) begin
                        if (next_slot >= slots) begin
                            slot$d = 32'h0;
                            slot_offset$d = 32'h0;
                        end
                        else begin
                            slot$d = next_slot;
                            slot_offset$d = slot_offset$q + slot_stride;
                        end
                    end
                end
        endcase
        if (stalled) begin
            if ((stall$q == bus_timeout) & ~timed_out$q) begin
                dma_status_bus_timeout_set = 1'b1;
                flags$d = flags$q | bus_timeout_flag;
                timed_out$d = 1'b1;
            end
            if (~&stall$q) begin
                stall$d = stall$q + 32'h1;
            end
        end
        if (accepted) begin
            stall$d = 32'h0;
            timed_out$d = 1'b0;
        end
        beats$read = pop;
        enables$read = pop;
        if (beat_push & ~pop) begin
            queued$d = queued$q + 32'h1;
        end
        if (pop & ~beat_push) begin
            queued$d = queued$q - 32'h1;
        end
        dma_status_busy = state$q != WriterState$Idle;
        dma_status_slot = slot$q;
        dma_frames_written_count = frames_written$q;
    end
    
endmodule // skylux_core$capture$writer


module skylux_core$capture$writer$addr(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$writer$addr


module skylux_core$capture$writer$beats(clock,read,data_out,empty,almost_empty,underflow,write,data_in,full,almost_full,overflow);
    
    // Module arguments
    input wire  clock;
    input wire  read;
    output reg  [63:0] data_out;
    output reg  empty;
    output reg  almost_empty;
    output reg  underflow;
    input wire  write;
    input wire  [63:0] data_in;
    output reg  full;
    output reg  almost_full;
    output reg  overflow;
    
    // Stub signals
    reg  [7:0] ram$read_address;
    reg  ram$read_clock;
    wire  [63:0] ram$read_data;
    reg  [7:0] ram$write_address;
    reg  ram$write_clock;
    reg  [63:0] ram$write_data;
    reg  ram$write_enable;
    reg  read_logic$clock;
    reg  read_logic$read;
    wire  [63:0] read_logic$data_out;
    wire  read_logic$empty;
    wire  read_logic$almost_empty;
    wire  read_logic$underflow;
    reg  [8:0] read_logic$write_address_delayed;
    wire  [7:0] read_logic$ram_read_address;
    reg  [63:0] read_logic$ram_read_data;
    wire  read_logic$ram_read_clock;
    wire  [8:0] read_logic$read_address_out;
    wire  [8:0] read_logic$fill_level;
    reg  write_logic$write;
    reg  [63:0] write_logic$data_in;
    wire  write_logic$full;
    wire  write_logic$almost_full;
    wire  write_logic$overflow;
    reg  write_logic$clock;
    wire  [7:0] write_logic$ram_write_address;
    wire  write_logic$ram_write_clock;
    wire  [63:0] write_logic$ram_write_data;
    wire  write_logic$ram_write_enable;
    reg  [8:0] write_logic$read_address;
    wire  [8:0] write_logic$write_address_delayed;
    wire  [8:0] write_logic$fill_level;
    
    // Sub module instances
    skylux_core$capture$writer$beats$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    skylux_core$capture$writer$beats$read_logic read_logic(
        .clock(read_logic$clock),
        .read(read_logic$read),
        .data_out(read_logic$data_out),
        .empty(read_logic$empty),
        .almost_empty(read_logic$almost_empty),
        .underflow(read_logic$underflow),
        .write_address_delayed(read_logic$write_address_delayed),
        .ram_read_address(read_logic$ram_read_address),
        .ram_read_data(read_logic$ram_read_data),
        .ram_read_clock(read_logic$ram_read_clock),
        .read_address_out(read_logic$read_address_out),
        .fill_level(read_logic$fill_level)
    );
    skylux_core$capture$writer$beats$write_logic write_logic(
        .write(write_logic$write),
        .data_in(write_logic$data_in),
        .full(write_logic$full),
        .almost_full(write_logic$almost_full),
        .overflow(write_logic$overflow),
        .clock(write_logic$clock),
        .ram_write_address(write_logic$ram_write_address),
        .ram_write_clock(write_logic$ram_write_clock),
        .ram_write_data(write_logic$ram_write_data),
        .ram_write_enable(write_logic$ram_write_enable),
        .read_address(write_logic$read_address),
        .write_address_delayed(write_logic$write_address_delayed),
        .fill_level(write_logic$fill_level)
    );
    
    // Update code
    always @(*) begin
        read_logic$clock = clock;
        write_logic$clock = clock;
        read_logic$read = read;
        empty = read_logic$empty;
        almost_empty = read_logic$almost_empty;
        data_out = read_logic$data_out;
        underflow = read_logic$underflow;
        overflow = write_logic$overflow;
        almost_full = write_logic$almost_full;
        full = write_logic$full;
        write_logic$write = write;
        write_logic$data_in = data_in;
        ram$write_clock = clock;
        ram$write_enable = write_logic$ram_write_enable;
        ram$write_address = write_logic$ram_write_address;
        ram$write_data = write_logic$ram_write_data;
        ram$read_clock = clock;
        ram$read_address = read_logic$ram_read_address;
        read_logic$ram_read_data = ram$read_data;
        read_logic$write_address_delayed = write_logic$write_address_delayed;
        write_logic$read_address = read_logic$read_address_out;
    end
    
endmodule // skylux_core$capture$writer$beats


module skylux_core$capture$writer$beats$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [7:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [7:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[63:0] mem[255:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // skylux_core$capture$writer$beats$ram


module skylux_core$capture$writer$beats$read_logic(clock,read,data_out,empty,almost_empty,underflow,write_address_delayed,ram_read_address,ram_read_data,ram_read_clock,read_address_out,fill_level);
    
    // Module arguments
    input wire  clock;
    input wire  read;
    output reg  [63:0] data_out;
    output reg  empty;
    output reg  almost_empty;
    output reg  underflow;
    input wire  [8:0] write_address_delayed;
    output reg  [7:0] ram_read_address;
    input wire  [63:0] ram_read_data;
    output reg  ram_read_clock;
    output reg  [8:0] read_address_out;
    output reg  [8:0] fill_level;
    
    // Constant declarations
    localparam  fifo_address_mask = 9'b11111111;
    localparam  fifo_size = 9'b100000000;
    localparam  block_size = 9'b1;
    
    // Stub signals
    reg  [8:0] read_address$d;
    wire  [8:0] read_address$q;
    reg  read_address$clock;
    reg  dff_underflow$d;
    wire  dff_underflow$q;
    reg  dff_underflow$clock;
    
    // Local signals
    reg  is_empty;
    reg  is_full;
    
    // Sub module instances
    skylux_core$capture$writer$beats$read_logic$read_address read_address(
        .d(read_address$d),
        .q(read_address$q),
        .clock(read_address$clock)
    );
    skylux_core$capture$writer$beats$read_logic$dff_underflow dff_underflow(
        .d(dff_underflow$d),
        .q(dff_underflow$q),
        .clock(dff_underflow$clock)
    );
    
    // Update code
    always @(*) begin
        read_address$clock = clock;
        dff_underflow$clock = clock;
        read_address$d = read_address$q;
        dff_underflow$d = dff_underflow$q;
        ram_read_clock = clock;
        is_empty = (read_address$q == write_address_delayed);
        is_full = ~is_empty & ((read_address$q & fifo_address_mask) == (write_address_delayed & fifo_address_mask));
        fill_level = ((write_address_delayed & fifo_address_mask) + fifo_size - (read_address$q & fifo_address_mask)) & fifo_address_mask;
        if (is_full) begin
            fill_level = fifo_size;
        end
        almost_empty = (fill_level < block_size);
        empty = is_empty;
        ram_read_address = ((read_address$q & fifo_address_mask) & 8'hff);
        data_out = ram_read_data;
        if (read & ~is_empty) begin
            read_address$d = read_address$q + 32'h1;
            ram_read_address = (((read_address$q + 32'h1) & fifo_address_mask) & 8'hff);
        end
        else begin
            read_address$d = read_address$q;
        end
        dff_underflow$d = dff_underflow$q | (is_empty & read);
        underflow = dff_underflow$q;
        read_address_out = read_address$q;
    end
    
endmodule // skylux_core$capture$writer$beats$read_logic


module skylux_core$capture$writer$beats$read_logic$dff_underflow(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$writer$beats$read_logic$dff_underflow


module skylux_core$capture$writer$beats$read_logic$read_address(d,q,clock);
    
    // Module arguments
    input wire  [8:0] d;
    output reg  [8:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 9'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$writer$beats$read_logic$read_address


module skylux_core$capture$writer$beats$write_logic(write,data_in,full,almost_full,overflow,clock,ram_write_address,ram_write_clock,ram_write_data,ram_write_enable,read_address,write_address_delayed,fill_level);
    
    // Module arguments
    input wire  write;
    input wire  [63:0] data_in;
    output reg  full;
    output reg  almost_full;
    output reg  overflow;
    input wire  clock;
    output reg  [7:0] ram_write_address;
    output reg  ram_write_clock;
    output reg  [63:0] ram_write_data;
    output reg  ram_write_enable;
    input wire  [8:0] read_address;
    output reg  [8:0] write_address_delayed;
    output reg  [8:0] fill_level;
    
    // Constant declarations
    localparam  fifo_address_mask = 9'b11111111;
    localparam  fifo_size = 9'b100000000;
    localparam  almost_full_level = 9'b11111111;
    
    // Stub signals
    reg  [8:0] write_address$d;
    wire  [8:0] write_address$q;
    reg  write_address$clock;
    reg  [8:0] dff_write_address_delay$d;
    wire  [8:0] dff_write_address_delay$q;
    reg  dff_write_address_delay$clock;
    reg  dff_overflow$d;
    wire  dff_overflow$q;
    reg  dff_overflow$clock;
    
    // Local signals
    reg  is_empty;
    reg  is_full;
    
    // Sub module instances
    skylux_core$capture$writer$beats$write_logic$write_address write_address(
        .d(write_address$d),
        .q(write_address$q),
        .clock(write_address$clock)
    );
    skylux_core$capture$writer$beats$write_logic$dff_write_address_delay dff_write_address_delay(
        .d(dff_write_address_delay$d),
        .q(dff_write_address_delay$q),
        .clock(dff_write_address_delay$clock)
    );
    skylux_core$capture$writer$beats$write_logic$dff_overflow dff_overflow(
        .d(dff_overflow$d),
        .q(dff_overflow$q),
        .clock(dff_overflow$clock)
    );
    
    // Update code
    always @(*) begin
        dff_overflow$clock = clock;
        write_address$clock = clock;
        dff_write_address_delay$clock = clock;
        dff_overflow$d = dff_overflow$q;
        write_address$d = write_address$q;
        dff_write_address_delay$d = dff_write_address_delay$q;
        ram_write_clock = clock;
        dff_write_address_delay$d = write_address$q;
        write_address_delayed = dff_write_address_delay$q;
        ram_write_enable = 1'b0;
        is_empty = (read_address == dff_write_address_delay$q);
        is_full = ~is_empty & ((read_address & fifo_address_mask) == (write_address$q & fifo_address_mask));
        fill_level = ((dff_write_address_delay$q & fifo_address_mask) + fifo_size - (read_address & fifo_address_mask)) & fifo_address_mask;
        if (is_full) begin
            fill_level = fifo_size;
        end
        almost_full = (fill_level >= almost_full_level);
        full = is_full;
        ram_write_address = ((write_address$q & fifo_address_mask) & 8'hff);
        ram_write_data = data_in;
        if (write & ~is_full) begin
            write_address$d = write_address$q + 32'h1;
            ram_write_enable = 1'b1;
        end
        else begin
            write_address$d = write_address$q;
            ram_write_enable = 1'b0;
        end
        dff_overflow$d = dff_overflow$q | (is_full & write);
        overflow = dff_overflow$q;
    end
    
endmodule // skylux_core$capture$writer$beats$write_logic


module skylux_core$capture$writer$beats$write_logic$dff_overflow(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$writer$beats$write_logic$dff_overflow


module skylux_core$capture$writer$beats$write_logic$dff_write_address_delay(d,q,clock);
    
    // Module arguments
    input wire  [8:0] d;
    output reg  [8:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 9'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$writer$beats$write_logic$dff_write_address_delay


module skylux_core$capture$writer$beats$write_logic$write_address(d,q,clock);
    
    // Module arguments
    input wire  [8:0] d;
    output reg  [8:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 9'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$writer$beats$write_logic$write_address


module skylux_core$capture$writer$beats_left(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$writer$beats_left


module skylux_core$capture$writer$burst_len(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$writer$burst_len


module skylux_core$capture$writer$desc_beat(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$writer$desc_beat


module skylux_core$capture$writer$enables(clock,read,data_out,empty,almost_empty,underflow,write,data_in,full,almost_full,overflow);
    
    // Module arguments
    input wire  clock;
    input wire  read;
    output reg  [7:0] data_out;
    output reg  empty;
    output reg  almost_empty;
    output reg  underflow;
    input wire  write;
    input wire  [7:0] data_in;
    output reg  full;
    output reg  almost_full;
    output reg  overflow;
    
    // Stub signals
    reg  [7:0] ram$read_address;
    reg  ram$read_clock;
    wire  [7:0] ram$read_data;
    reg  [7:0] ram$write_address;
    reg  ram$write_clock;
    reg  [7:0] ram$write_data;
    reg  ram$write_enable;
    reg  read_logic$clock;
    reg  read_logic$read;
    wire  [7:0] read_logic$data_out;
    wire  read_logic$empty;
    wire  read_logic$almost_empty;
    wire  read_logic$underflow;
    reg  [8:0] read_logic$write_address_delayed;
    wire  [7:0] read_logic$ram_read_address;
    reg  [7:0] read_logic$ram_read_data;
    wire  read_logic$ram_read_clock;
    wire  [8:0] read_logic$read_address_out;
    wire  [8:0] read_logic$fill_level;
    reg  write_logic$write;
    reg  [7:0] write_logic$data_in;
    wire  write_logic$full;
    wire  write_logic$almost_full;
    wire  write_logic$overflow;
    reg  write_logic$clock;
    wire  [7:0] write_logic$ram_write_address;
    wire  write_logic$ram_write_clock;
    wire  [7:0] write_logic$ram_write_data;
    wire  write_logic$ram_write_enable;
    reg  [8:0] write_logic$read_address;
    wire  [8:0] write_logic$write_address_delayed;
    wire  [8:0] write_logic$fill_level;
    
    // Sub module instances
    skylux_core$capture$writer$enables$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    skylux_core$capture$writer$enables$read_logic read_logic(
        .clock(read_logic$clock),
        .read(read_logic$read),
        .data_out(read_logic$data_out),
        .empty(read_logic$empty),
        .almost_empty(read_logic$almost_empty),
        .underflow(read_logic$underflow),
        .write_address_delayed(read_logic$write_address_delayed),
        .ram_read_address(read_logic$ram_read_address),
        .ram_read_data(read_logic$ram_read_data),
        .ram_read_clock(read_logic$ram_read_clock),
        .read_address_out(read_logic$read_address_out),
        .fill_level(read_logic$fill_level)
    );
    skylux_core$capture$writer$enables$write_logic write_logic(
        .write(write_logic$write),
        .data_in(write_logic$data_in),
        .full(write_logic$full),
        .almost_full(write_logic$almost_full),
        .overflow(write_logic$overflow),
        .clock(write_logic$clock),
        .ram_write_address(write_logic$ram_write_address),
        .ram_write_clock(write_logic$ram_write_clock),
        .ram_write_data(write_logic$ram_write_data),
        .ram_write_enable(write_logic$ram_write_enable),
        .read_address(write_logic$read_address),
        .write_address_delayed(write_logic$write_address_delayed),
        .fill_level(write_logic$fill_level)
    );
    
    // Update code
    always @(*) begin
        read_logic$clock = clock;
        write_logic$clock = clock;
        read_logic$read = read;
        empty = read_logic$empty;
        almost_empty = read_logic$almost_empty;
        data_out = read_logic$data_out;
        underflow = read_logic$underflow;
        overflow = write_logic$overflow;
        almost_full = write_logic$almost_full;
        full = write_logic$full;
        write_logic$write = write;
        write_logic$data_in = data_in;
        ram$write_clock = clock;
        ram$write_enable = write_logic$ram_write_enable;
        ram$write_address = write_logic$ram_write_address;
        ram$write_data = write_logic$ram_write_data;
        ram$read_clock = clock;
        ram$read_address = read_logic$ram_read_address;
        read_logic$ram_read_data = ram$read_data;
        read_logic$write_address_delayed = write_logic$write_address_delayed;
        write_logic$read_address = read_logic$read_address_out;
    end
    
endmodule // skylux_core$capture$writer$enables


module skylux_core$capture$writer$enables$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [7:0] read_address;
    input wire  read_clock;
    output reg  [7:0] read_data;
    input wire  [7:0] write_address;
    input wire  write_clock;
    input wire  [7:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[7:0] mem[255:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // skylux_core$capture$writer$enables$ram


module skylux_core$capture$writer$enables$read_logic(clock,read,data_out,empty,almost_empty,underflow,write_address_delayed,ram_read_address,ram_read_data,ram_read_clock,read_address_out,fill_level);
    
    // Module arguments
    input wire  clock;
    input wire  read;
    output reg  [7:0] data_out;
    output reg  empty;
    output reg  almost_empty;
    output reg  underflow;
    input wire  [8:0] write_address_delayed;
    output reg  [7:0] ram_read_address;
    input wire  [7:0] ram_read_data;
    output reg  ram_read_clock;
    output reg  [8:0] read_address_out;
    output reg  [8:0] fill_level;
    
    // Constant declarations
    localparam  fifo_address_mask = 9'b11111111;
    localparam  fifo_size = 9'b100000000;
    localparam  block_size = 9'b1;
    
    // Stub signals
    reg  [8:0] read_address$d;
    wire  [8:0] read_address$q;
    reg  read_address$clock;
    reg  dff_underflow$d;
    wire  dff_underflow$q;
    reg  dff_underflow$clock;
    
    // Local signals
    reg  is_empty;
    reg  is_full;
    
    // Sub module instances
    skylux_core$capture$writer$enables$read_logic$read_address read_address(
        .d(read_address$d),
        .q(read_address$q),
        .clock(read_address$clock)
    );
    skylux_core$capture$writer$enables$read_logic$dff_underflow dff_underflow(
        .d(dff_underflow$d),
        .q(dff_underflow$q),
        .clock(dff_underflow$clock)
    );
    
    // Update code
    always @(*) begin
        read_address$clock = clock;
        dff_underflow$clock = clock;
        read_address$d = read_address$q;
        dff_underflow$d = dff_underflow$q;
        ram_read_clock = clock;
        is_empty = (read_address$q == write_address_delayed);
        is_full = ~is_empty & ((read_address$q & fifo_address_mask) == (write_address_delayed & fifo_address_mask));
        fill_level = ((write_address_delayed & fifo_address_mask) + fifo_size - (read_address$q & fifo_address_mask)) & fifo_address_mask;
        if (is_full) begin
            fill_level = fifo_size;
        end
        almost_empty = (fill_level < block_size);
        empty = is_empty;
        ram_read_address = ((read_address$q & fifo_address_mask) & 8'hff);
        data_out = ram_read_data;
        if (read & ~is_empty) begin
            read_address$d = read_address$q + 32'h1;
            ram_read_address = (((read_address$q + 32'h1) & fifo_address_mask) & 8'hff);
        end
        else begin
            read_address$d = read_address$q;
        end
        dff_underflow$d = dff_underflow$q | (is_empty & read);
        underflow = dff_underflow$q;
        read_address_out = read_address$q;
    end
    
endmodule // skylux_core$capture$writer$enables$read_logic


module skylux_core$capture$writer$enables$read_logic$dff_underflow(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$writer$enables$read_logic$dff_underflow


module skylux_core$capture$writer$enables$read_logic$read_address(d,q,clock);
    
    // Module arguments
    input wire  [8:0] d;
    output reg  [8:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 9'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$writer$enables$read_logic$read_address


module skylux_core$capture$writer$enables$write_logic(write,data_in,full,almost_full,overflow,clock,ram_write_address,ram_write_clock,ram_write_data,ram_write_enable,read_address,write_address_delayed,fill_level);
    
    // Module arguments
    input wire  write;
    input wire  [7:0] data_in;
    output reg  full;
    output reg  almost_full;
    output reg  overflow;
    input wire  clock;
    output reg  [7:0] ram_write_address;
    output reg  ram_write_clock;
    output reg  [7:0] ram_write_data;
    output reg  ram_write_enable;
    input wire  [8:0] read_address;
    output reg  [8:0] write_address_delayed;
    output reg  [8:0] fill_level;
    
    // Constant declarations
    localparam  fifo_address_mask = 9'b11111111;
    localparam  fifo_size = 9'b100000000;
    localparam  almost_full_level = 9'b11111111;
    
    // Stub signals
    reg  [8:0] write_address$d;
    wire  [8:0] write_address$q;
    reg  write_address$clock;
    reg  [8:0] dff_write_address_delay$d;
    wire  [8:0] dff_write_address_delay$q;
    reg  dff_write_address_delay$clock;
    reg  dff_overflow$d;
    wire  dff_overflow$q;
    reg  dff_overflow$clock;
    
    // Local signals
    reg  is_empty;
    reg  is_full;
    
    // Sub module instances
    skylux_core$capture$writer$enables$write_logic$write_address write_address(
        .d(write_address$d),
        .q(write_address$q),
        .clock(write_address$clock)
    );
    skylux_core$capture$writer$enables$write_logic$dff_write_address_delay dff_write_address_delay(
        .d(dff_write_address_delay$d),
        .q(dff_write_address_delay$q),
        .clock(dff_write_address_delay$clock)
    );
    skylux_core$capture$writer$enables$write_logic$dff_overflow dff_overflow(
        .d(dff_overflow$d),
        .q(dff_overflow$q),
        .clock(dff_overflow$clock)
    );
    
    // Update code
    always @(*) begin
        dff_overflow$clock = clock;
        write_address$clock = clock;
        dff_write_address_delay$clock = clock;
        dff_overflow$d = dff_overflow$q;
        write_address$d = write_address$q;
        dff_write_address_delay$d = dff_write_address_delay$q;
        ram_write_clock = clock;
        dff_write_address_delay$d = write_address$q;
        write_address_delayed = dff_write_address_delay$q;
        ram_write_enable = 1'b0;
        is_empty = (read_address == dff_write_address_delay$q);
        is_full = ~is_empty & ((read_address & fifo_address_mask) == (write_address$q & fifo_address_mask));
        fill_level = ((dff_write_address_delay$q & fifo_address_mask) + fifo_size - (read_address & fifo_address_mask)) & fifo_address_mask;
        if (is_full) begin
            fill_level = fifo_size;
        end
        almost_full = (fill_level >= almost_full_level);
        full = is_full;
        ram_write_address = ((write_address$q & fifo_address_mask) & 8'hff);
        ram_write_data = data_in;
        if (write & ~is_full) begin
            write_address$d = write_address$q + 32'h1;
            ram_write_enable = 1'b1;
        end
        else begin
            write_address$d = write_address$q;
            ram_write_enable = 1'b0;
        end
        dff_overflow$d = dff_overflow$q | (is_full & write);
        overflow = dff_overflow$q;
    end
    
endmodule // skylux_core$capture$writer$enables$write_logic


module skylux_core$capture$writer$enables$write_logic$dff_overflow(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$writer$enables$write_logic$dff_overflow


module skylux_core$capture$writer$enables$write_logic$dff_write_address_delay(d,q,clock);
    
    // Module arguments
    input wire  [8:0] d;
    output reg  [8:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 9'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$writer$enables$write_logic$dff_write_address_delay


module skylux_core$capture$writer$enables$write_logic$write_address(d,q,clock);
    
    // Module arguments
    input wire  [8:0] d;
    output reg  [8:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 9'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$writer$enables$write_logic$write_address


module skylux_core$capture$writer$flags(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$writer$flags


module skylux_core$capture$writer$frames_written(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$writer$frames_written


module skylux_core$capture$writer$queued(d,q,clock);
    
    // Module arguments
    input wire  [8:0] d;
    output reg  [8:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 9'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$writer$queued


module skylux_core$capture$writer$restart_pending(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$writer$restart_pending


module skylux_core$capture$writer$slot(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$writer$slot


module skylux_core$capture$writer$slot_addr(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$writer$slot_addr


module skylux_core$capture$writer$slot_end(d,q,clock);
    
    // Module arguments
    input wire  [32:0] d;
    output reg  [32:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 33'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$writer$slot_end


module skylux_core$capture$writer$slot_offset(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$writer$slot_offset


module skylux_core$capture$writer$slot_ok(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$writer$slot_ok


module skylux_core$capture$writer$stall(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$writer$stall


module skylux_core$capture$writer$state(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Enums
    localparam WriterState$Idle = 0;
    localparam WriterState$Plan = 1;
    localparam WriterState$Burst = 2;
    localparam WriterState$Drain = 3;
    localparam WriterState$Descriptor = 4;
    localparam WriterState$Close = 5;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$writer$state


module skylux_core$capture$writer$timed_out(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$capture$writer$timed_out


module skylux_core$raybox(clock,ctrl_start,ctrl_abort,work_base_addr,work_count_items,result_base_addr,window_base_addr,window_size_bytes,bus_timeout_cycles,status_busy,status_done_set,status_bad_descriptor_set,status_out_of_window_set,status_bus_timeout_set,tests_done_count,info_lanes,rbx_address,rbx_burstcount,rbx_read,rbx_write,rbx_writedata,rbx_byteenable,rbx_waitrequest,rbx_readdata,rbx_readdatavalid);
    
    // Module arguments
    input wire  clock;
    input wire  ctrl_start;
    input wire  ctrl_abort;
    input wire  [31:0] work_base_addr;
    input wire  [23:0] work_count_items;
    input wire  [31:0] result_base_addr;
    input wire  [31:0] window_base_addr;
    input wire  [31:0] window_size_bytes;
    input wire  [23:0] bus_timeout_cycles;
    output reg  status_busy;
    output reg  status_done_set;
    output reg  status_bad_descriptor_set;
    output reg  status_out_of_window_set;
    output reg  status_bus_timeout_set;
    output reg  [31:0] tests_done_count;
    output reg  [7:0] info_lanes;
    output reg  [28:0] rbx_address;
    output reg  [7:0] rbx_burstcount;
    output reg  rbx_read;
    output reg  rbx_write;
    output reg  [63:0] rbx_writedata;
    output reg  [7:0] rbx_byteenable;
    input wire  rbx_waitrequest;
    input wire  [63:0] rbx_readdata;
    input wire  rbx_readdatavalid;
    
    // Constant declarations
    localparam  lanes_value = 8'h1;
    localparam  last_lane = 16'h1;
    localparam  magic = 8'hb7;
    localparam  item_words_addr = 29'h6;
    localparam  item_words_burst = 8'h6;
    localparam  item_words_count = 5'b110;
    localparam  read_limit = 5'b1010;
    localparam  fifo_depth = 5'b10000;
    
    // Enums
    localparam UnitState$Idle = 0;
    localparam UnitState$Check = 1;
    localparam UnitState$Run = 2;
    localparam UnitState$Finish = 3;
    
    // Stub signals
    reg  lanes$0$clock;
    reg  lanes$0$in_valid;
    reg  [23:0] lanes$0$in_index;
    reg  [62:0] lanes$0$origin;
    reg  [62:0] lanes$0$entry_plane;
    reg  [62:0] lanes$0$exit_plane;
    reg  [74:0] lanes$0$mant;
    reg  [17:0] lanes$0$shift;
    reg  [31:0] lanes$0$t_min;
    reg  [31:0] lanes$0$t_max;
    wire  lanes$0$out_valid;
    wire  [23:0] lanes$0$out_index;
    wire  lanes$0$out_hit;
    wire  [31:0] lanes$0$out_t_near;
    reg  read_fifo$clock;
    reg  read_fifo$read;
    wire  [63:0] read_fifo$data_out;
    wire  read_fifo$empty;
    wire  read_fifo$almost_empty;
    wire  read_fifo$underflow;
    reg  read_fifo$write;
    reg  [63:0] read_fifo$data_in;
    wire  read_fifo$full;
    wire  read_fifo$almost_full;
    wire  read_fifo$overflow;
    reg  result_fifo$clock;
    reg  result_fifo$read;
    wire  [63:0] result_fifo$data_out;
    wire  result_fifo$empty;
    wire  result_fifo$almost_empty;
    wire  result_fifo$underflow;
    reg  result_fifo$write;
    reg  [63:0] result_fifo$data_in;
    wire  result_fifo$full;
    wire  result_fifo$almost_full;
    wire  result_fifo$overflow;
    reg  [1:0] state$d;
    wire  [1:0] state$q;
    reg  state$clock;
    reg  [31:0] base_work$d;
    wire  [31:0] base_work$q;
    reg  base_work$clock;
    reg  [31:0] base_result$d;
    wire  [31:0] base_result$q;
    reg  base_result$clock;
    reg  [23:0] count$d;
    wire  [23:0] count$q;
    reg  count$clock;
    reg  [28:0] work_addr$d;
    wire  [28:0] work_addr$q;
    reg  work_addr$clock;
    reg  [28:0] result_addr$d;
    wire  [28:0] result_addr$q;
    reg  result_addr$clock;
    reg  [23:0] requested$d;
    wire  [23:0] requested$q;
    reg  requested$clock;
    reg  [23:0] issued$d;
    wire  [23:0] issued$q;
    reg  issued$clock;
    reg  [23:0] written$d;
    wire  [23:0] written$q;
    reg  written$clock;
    reg  [4:0] reserved$d;
    wire  [4:0] reserved$q;
    reg  reserved$clock;
    reg  [4:0] outstanding$d;
    wire  [4:0] outstanding$q;
    reg  outstanding$clock;
    reg  [4:0] stale$d;
    wire  [4:0] stale$q;
    reg  stale$clock;
    reg  [4:0] in_flight$d;
    wire  [4:0] in_flight$q;
    reg  in_flight$clock;
    reg  [2:0] word_index$d;
    wire  [2:0] word_index$q;
    reg  word_index$clock;
    reg  item_ready$d;
    wire  item_ready$q;
    reg  item_ready$clock;
    reg  [15:0] lane_select$d;
    wire  [15:0] lane_select$q;
    reg  lane_select$clock;
    reg  [23:0] watchdog$d;
    wire  [23:0] watchdog$q;
    reg  watchdog$clock;
    reg  refused$d;
    wire  refused$q;
    reg  refused$clock;
    reg  cmd_read$d;
    wire  cmd_read$q;
    reg  cmd_read$clock;
    reg  cmd_write$d;
    wire  cmd_write$q;
    reg  cmd_write$clock;
    reg  [28:0] cmd_addr$d;
    wire  [28:0] cmd_addr$q;
    reg  cmd_addr$clock;
    reg  [7:0] cmd_burst$d;
    wire  [7:0] cmd_burst$q;
    reg  cmd_burst$clock;
    reg  [63:0] cmd_data$d;
    wire  [63:0] cmd_data$q;
    reg  cmd_data$clock;
    reg  done_pulse$d;
    wire  done_pulse$q;
    reg  done_pulse$clock;
    reg  bad_pulse$d;
    wire  bad_pulse$q;
    reg  bad_pulse$clock;
    reg  window_pulse$d;
    wire  window_pulse$q;
    reg  window_pulse$clock;
    reg  timeout_pulse$d;
    wire  timeout_pulse$q;
    reg  timeout_pulse$clock;
    reg  [62:0] origin$d;
    wire  [62:0] origin$q;
    reg  origin$clock;
    reg  [62:0] entry_plane$d;
    wire  [62:0] entry_plane$q;
    reg  entry_plane$clock;
    reg  [62:0] exit_plane$d;
    wire  [62:0] exit_plane$q;
    reg  exit_plane$clock;
    reg  [49:0] mant_xy$d;
    wire  [49:0] mant_xy$q;
    reg  mant_xy$clock;
    reg  [24:0] mant_z$d;
    wire  [24:0] mant_z$q;
    reg  mant_z$clock;
    reg  [11:0] shift_xy$d;
    wire  [11:0] shift_xy$q;
    reg  shift_xy$clock;
    reg  [5:0] shift_z$d;
    wire  [5:0] shift_z$q;
    reg  shift_z$clock;
    reg  [31:0] t_min$d;
    wire  [31:0] t_min$q;
    reg  t_min$clock;
    reg  [31:0] t_max$d;
    wire  [31:0] t_max$q;
    reg  t_max$clock;
    
    // Local signals
    reg  [33:0] work_lo;
    reg  [33:0] work_hi;
    reg  [33:0] result_lo;
    reg  [33:0] result_hi;
    reg  [33:0] window_lo;
    reg  [33:0] window_hi;
    reg  [33:0] count_wide;
    reg  accepted;
    reg  cmd_free;
    reg  beat;
    reg  issue;
    reg  pop;
    reg  [63:0] head;
    reg  [4:0] reserved_n;
    reg  [4:0] outstanding_n;
    reg  [4:0] in_flight_n;
    reg  lane_valid;
    reg  lane_hit;
    reg  [23:0] lane_index;
    reg  [31:0] lane_t_near;
    reg  waiting;
    reg  [23:0] watchdog_n;
    reg  timed_out;
    reg  more_to_read;
    reg  room_to_read;
    
    // Sub module instances
    skylux_core$raybox$lanes$0 lanes$0(
        .clock(lanes$0$clock),
        .in_valid(lanes$0$in_valid),
        .in_index(lanes$0$in_index),
        .origin(lanes$0$origin),
        .entry_plane(lanes$0$entry_plane),
        .exit_plane(lanes$0$exit_plane),
        .mant(lanes$0$mant),
        .shift(lanes$0$shift),
        .t_min(lanes$0$t_min),
        .t_max(lanes$0$t_max),
        .out_valid(lanes$0$out_valid),
        .out_index(lanes$0$out_index),
        .out_hit(lanes$0$out_hit),
        .out_t_near(lanes$0$out_t_near)
    );
    skylux_core$raybox$read_fifo read_fifo(
        .clock(read_fifo$clock),
        .read(read_fifo$read),
        .data_out(read_fifo$data_out),
        .empty(read_fifo$empty),
        .almost_empty(read_fifo$almost_empty),
        .underflow(read_fifo$underflow),
        .write(read_fifo$write),
        .data_in(read_fifo$data_in),
        .full(read_fifo$full),
        .almost_full(read_fifo$almost_full),
        .overflow(read_fifo$overflow)
    );
    skylux_core$raybox$result_fifo result_fifo(
        .clock(result_fifo$clock),
        .read(result_fifo$read),
        .data_out(result_fifo$data_out),
        .empty(result_fifo$empty),
        .almost_empty(result_fifo$almost_empty),
        .underflow(result_fifo$underflow),
        .write(result_fifo$write),
        .data_in(result_fifo$data_in),
        .full(result_fifo$full),
        .almost_full(result_fifo$almost_full),
        .overflow(result_fifo$overflow)
    );
    skylux_core$raybox$state state(
        .d(state$d),
        .q(state$q),
        .clock(state$clock)
    );
    skylux_core$raybox$base_work base_work(
        .d(base_work$d),
        .q(base_work$q),
        .clock(base_work$clock)
    );
    skylux_core$raybox$base_result base_result(
        .d(base_result$d),
        .q(base_result$q),
        .clock(base_result$clock)
    );
    skylux_core$raybox$count count(
        .d(count$d),
        .q(count$q),
        .clock(count$clock)
    );
    skylux_core$raybox$work_addr work_addr(
        .d(work_addr$d),
        .q(work_addr$q),
        .clock(work_addr$clock)
    );
    skylux_core$raybox$result_addr result_addr(
        .d(result_addr$d),
        .q(result_addr$q),
        .clock(result_addr$clock)
    );
    skylux_core$raybox$requested requested(
        .d(requested$d),
        .q(requested$q),
        .clock(requested$clock)
    );
    skylux_core$raybox$issued issued(
        .d(issued$d),
        .q(issued$q),
        .clock(issued$clock)
    );
    skylux_core$raybox$written written(
        .d(written$d),
        .q(written$q),
        .clock(written$clock)
    );
    skylux_core$raybox$reserved reserved(
        .d(reserved$d),
        .q(reserved$q),
        .clock(reserved$clock)
    );
    skylux_core$raybox$outstanding outstanding(
        .d(outstanding$d),
        .q(outstanding$q),
        .clock(outstanding$clock)
    );
    skylux_core$raybox$stale stale(
        .d(stale$d),
        .q(stale$q),
        .clock(stale$clock)
    );
    skylux_core$raybox$in_flight in_flight(
        .d(in_flight$d),
        .q(in_flight$q),
        .clock(in_flight$clock)
    );
    skylux_core$raybox$word_index word_index(
        .d(word_index$d),
        .q(word_index$q),
        .clock(word_index$clock)
    );
    skylux_core$raybox$item_ready item_ready(
        .d(item_ready$d),
        .q(item_ready$q),
        .clock(item_ready$clock)
    );
    skylux_core$raybox$lane_select lane_select(
        .d(lane_select$d),
        .q(lane_select$q),
        .clock(lane_select$clock)
    );
    skylux_core$raybox$watchdog watchdog(
        .d(watchdog$d),
        .q(watchdog$q),
        .clock(watchdog$clock)
    );
    skylux_core$raybox$refused refused(
        .d(refused$d),
        .q(refused$q),
        .clock(refused$clock)
    );
    skylux_core$raybox$cmd_read cmd_read(
        .d(cmd_read$d),
        .q(cmd_read$q),
        .clock(cmd_read$clock)
    );
    skylux_core$raybox$cmd_write cmd_write(
        .d(cmd_write$d),
        .q(cmd_write$q),
        .clock(cmd_write$clock)
    );
    skylux_core$raybox$cmd_addr cmd_addr(
        .d(cmd_addr$d),
        .q(cmd_addr$q),
        .clock(cmd_addr$clock)
    );
    skylux_core$raybox$cmd_burst cmd_burst(
        .d(cmd_burst$d),
        .q(cmd_burst$q),
        .clock(cmd_burst$clock)
    );
    skylux_core$raybox$cmd_data cmd_data(
        .d(cmd_data$d),
        .q(cmd_data$q),
        .clock(cmd_data$clock)
    );
    skylux_core$raybox$done_pulse done_pulse(
        .d(done_pulse$d),
        .q(done_pulse$q),
        .clock(done_pulse$clock)
    );
    skylux_core$raybox$bad_pulse bad_pulse(
        .d(bad_pulse$d),
        .q(bad_pulse$q),
        .clock(bad_pulse$clock)
    );
    skylux_core$raybox$window_pulse window_pulse(
        .d(window_pulse$d),
        .q(window_pulse$q),
        .clock(window_pulse$clock)
    );
    skylux_core$raybox$timeout_pulse timeout_pulse(
        .d(timeout_pulse$d),
        .q(timeout_pulse$q),
        .clock(timeout_pulse$clock)
    );
    skylux_core$raybox$origin origin(
        .d(origin$d),
        .q(origin$q),
        .clock(origin$clock)
    );
    skylux_core$raybox$entry_plane entry_plane(
        .d(entry_plane$d),
        .q(entry_plane$q),
        .clock(entry_plane$clock)
    );
    skylux_core$raybox$exit_plane exit_plane(
        .d(exit_plane$d),
        .q(exit_plane$q),
        .clock(exit_plane$clock)
    );
    skylux_core$raybox$mant_xy mant_xy(
        .d(mant_xy$d),
        .q(mant_xy$q),
        .clock(mant_xy$clock)
    );
    skylux_core$raybox$mant_z mant_z(
        .d(mant_z$d),
        .q(mant_z$q),
        .clock(mant_z$clock)
    );
    skylux_core$raybox$shift_xy shift_xy(
        .d(shift_xy$d),
        .q(shift_xy$q),
        .clock(shift_xy$clock)
    );
    skylux_core$raybox$shift_z shift_z(
        .d(shift_z$d),
        .q(shift_z$q),
        .clock(shift_z$clock)
    );
    skylux_core$raybox$t_min t_min(
        .d(t_min$d),
        .q(t_min$q),
        .clock(t_min$clock)
    );
    skylux_core$raybox$t_max t_max(
        .d(t_max$d),
        .q(t_max$q),
        .clock(t_max$clock)
    );
    
    // Update code
    always @(*) begin
        state$clock = clock;
        base_work$clock = clock;
        base_result$clock = clock;
        count$clock = clock;
        work_addr$clock = clock;
        result_addr$clock = clock;
        requested$clock = clock;
        issued$clock = clock;
        written$clock = clock;
        reserved$clock = clock;
        outstanding$clock = clock;
        stale$clock = clock;
        in_flight$clock = clock;
        word_index$clock = clock;
        item_ready$clock = clock;
        lane_select$clock = clock;
        watchdog$clock = clock;
        refused$clock = clock;
        cmd_read$clock = clock;
        cmd_write$clock = clock;
        cmd_addr$clock = clock;
        cmd_burst$clock = clock;
        cmd_data$clock = clock;
        done_pulse$clock = clock;
        bad_pulse$clock = clock;
        window_pulse$clock = clock;
        timeout_pulse$clock = clock;
        t_min$clock = clock;
        t_max$clock = clock;
        origin$clock = clock;
        entry_plane$clock = clock;
        exit_plane$clock = clock;
        mant_xy$clock = clock;
        mant_z$clock = clock;
        shift_xy$clock = clock;
        shift_z$clock = clock;
        state$d = state$q;
        base_work$d = base_work$q;
        base_result$d = base_result$q;
        count$d = count$q;
        work_addr$d = work_addr$q;
        result_addr$d = result_addr$q;
        requested$d = requested$q;
        issued$d = issued$q;
        written$d = written$q;
        reserved$d = reserved$q;
        outstanding$d = outstanding$q;
        stale$d = stale$q;
        in_flight$d = in_flight$q;
        word_index$d = word_index$q;
        item_ready$d = item_ready$q;
        lane_select$d = lane_select$q;
        watchdog$d = watchdog$q;
        refused$d = refused$q;
        cmd_read$d = cmd_read$q;
        cmd_write$d = cmd_write$q;
        cmd_addr$d = cmd_addr$q;
        cmd_burst$d = cmd_burst$q;
        cmd_data$d = cmd_data$q;
        done_pulse$d = done_pulse$q;
        bad_pulse$d = bad_pulse$q;
        window_pulse$d = window_pulse$q;
        timeout_pulse$d = timeout_pulse$q;
        t_min$d = t_min$q;
        t_max$d = t_max$q;
        origin$d = origin$q;
        entry_plane$d = entry_plane$q;
        exit_plane$d = exit_plane$q;
        mant_xy$d = mant_xy$q;
        mant_z$d = mant_z$q;
        shift_xy$d = shift_xy$q;
        shift_z$d = shift_z$q;
        read_fifo$clock = clock;
        result_fifo$clock = clock;
        done_pulse$d = 1'b0;
        bad_pulse$d = 1'b0;
        window_pulse$d = 1'b0;
        timeout_pulse$d = 1'b0;
        read_fifo$write = 1'b0;
        read_fifo$read = 1'b0;
        read_fifo$data_in = rbx_readdata;
        result_fifo$write = 1'b0;
        result_fifo$read = 1'b0;
        head = read_fifo$data_out;
        accepted = (cmd_read$q | cmd_write$q) & ~rbx_waitrequest;
        cmd_free = ~(cmd_read$q | cmd_write$q) | accepted;
        if (accepted) begin
            cmd_read$d = 1'b0;
            cmd_write$d = 1'b0;
        end
        beat = rbx_readdatavalid;
        outstanding_n = outstanding$q;
        if (accepted & cmd_read$q) begin
            outstanding_n = outstanding_n + item_words_count;
        end
        if (beat) begin
            if (|outstanding_n) begin
                outstanding_n = outstanding_n - 32'h1;
            end
            if (|stale$q) begin
                stale$d = stale$q - 32'h1;
            end
            else if (state$q == UnitState$Run) begin
                read_fifo$write = 1'b1;
            end
        end
        outstanding$d = outstanding_n;
        waiting = cmd_read$q | cmd_write$q | |outstanding$q;
        watchdog_n = 32'h0;
        if (waiting & ~accepted & ~beat) begin
            watchdog_n = watchdog$q + 32'h1;
        end
        watchdog$d = watchdog_n;
        timed_out = |bus_timeout_cycles & (watchdog_n == bus_timeout_cycles);
        issue = 1'b0;
        lane_valid = 1'b0;
        lane_hit = 1'b0;
        lane_index = 32'h0;
        lane_t_near = 32'h0;
        lanes$0$clock = clock;
        lanes$0$in_valid = 1'b0;
        lanes$0$in_index = issued$q;
        lanes$0$t_min = t_min$q;
        lanes$0$t_max = t_max$q;
        lanes$0$origin = origin$q;
        lanes$0$entry_plane = entry_plane$q;
        lanes$0$exit_plane = exit_plane$q;
        lanes$0$mant = ((mant_xy$q) & 75'h7ffffffffffffffffff) | (((mant_z$q) & 75'h7ffffffffffffffffff) << 32'h32);
        lanes$0$shift = ((shift_xy$q) & 18'h3ffff) | (((shift_z$q) & 18'h3ffff) << 32'hc);
        if (lanes$0$out_valid) begin
            lane_valid = 1'b1;
            lane_hit = lanes$0$out_hit;
            lane_index = lanes$0$out_index;
            lane_t_near = lanes$0$out_t_near;
        end
        result_fifo$data_in = ((lane_t_near) & 64'hffffffffffffffff) | (((lane_index) & 64'hffffffffffffffff) << 32'h20) | (((lane_hit) & 64'hffffffffffffffff) << 32'h3f);
        reserved_n = reserved$q;
        in_flight_n = in_flight$q;
        pop = 1'b0;
        more_to_read = requested$q < count$q;
        room_to_read = reserved$q <= read_limit;
        count_wide = ((count$q) & 34'h3ffffffff);
        work_lo = ((base_work$q) & 34'h3ffffffff);
        work_hi = work_lo + (count_wide << 32'h5) + (count_wide << 32'h4);
        result_lo = ((base_result$q) & 34'h3ffffffff);
        result_hi = result_lo + (count_wide << 32'h3);
        window_lo = ((window_base_addr) & 34'h3ffffffff);
        window_hi = window_lo + ((window_size_bytes) & 34'h3ffffffff);
        case (state$q)
            UnitState$Idle:
                begin
                    read_fifo$read = ~read_fifo$empty;
                    result_fifo$read = ~result_fifo$empty;
                    if (ctrl_start) begin
                        base_work$d = work_base_addr;
                        base_result$d = result_base_addr;
                        count$d = work_count_items;
                        requested$d = 32'h0;
                        issued$d = 32'h0;
                        written$d = 32'h0;
                        reserved_n = 32'h0;
                        in_flight_n = 32'h0;
                        word_index$d = 32'h0;
                        item_ready$d = 1'b0;
                        refused$d = 1'b0;
                        lane_select$d = 32'h1;
                        stale$d = outstanding_n;
                        state$d = UnitState$Check;
                    end
                end
            UnitState$Check:
                begin
                    read_fifo$read = ~read_fifo$empty;
                    result_fifo$read = ~result_fifo$empty;
                    work_addr$d = base_work$q[(32'h3)+:(29)];
                    result_addr$d = base_result$q[(32'h3)+:(29)];
                    if (|base_work$q[(32'h0)+:(3)] | |base_result$q[(32'h0)+:(3)]) begin
                        bad_pulse$d = 1'b1;
                        done_pulse$d = 1'b1;
                        state$d = UnitState$Idle;
                    end
                    else if ((work_lo < window_lo) | (work_hi > window_hi) | (result_lo < window_lo) | (result_hi > window_hi)) begin
                        window_pulse$d = 1'b1;
                        done_pulse$d = 1'b1;
                        state$d = UnitState$Idle;
                    end
                    else if (~|count$q) begin
                        done_pulse$d = 1'b1;
                        state$d = UnitState$Idle;
                    end
                    else begin
                        state$d = UnitState$Run;
                    end
                end
            UnitState$Run:
                begin
                    issue = item_ready$q & (in_flight$q < fifo_depth);
                    pop = ~read_fifo$empty & (~item_ready$q | issue);
                    if (ctrl_abort) begin
                        pop = 1'b0;
                        state$d = UnitState$Finish;
                    end
                end
            UnitState$Finish:
                begin
                    read_fifo$read = ~read_fifo$empty;
                    if (~|in_flight$q & ~cmd_read$q & ~cmd_write$q) begin
                        done_pulse$d = 1'b1;
                        bad_pulse$d = refused$q;
                        state$d = UnitState$Idle;
                    end
                end
        endcase
        if (issue) begin
            if (lane_select$q[0]) begin
                lanes$0$in_valid = 1'b1;
            end
            lane_select$d = lane_select$q << 32'h1;
            if (|(lane_select$q & last_lane)) begin
                lane_select$d = 32'h1;
            end
            issued$d = issued$q + 32'h1;
            in_flight_n = in_flight_n + 32'h1;
            item_ready$d = 1'b0;
            if (issued$q + 32'h1 == count$q) begin
                state$d = UnitState$Finish;
            end
        end
        if (pop) begin
            read_fifo$read = 1'b1;
            reserved_n = reserved_n - 32'h1;
            word_index$d = word_index$q + 32'h1;
            case (word_index$q)
                0:
                    begin
                        origin$d = head[(32'h0)+:(63)];
                    end
                1:
                    begin
                        entry_plane$d = head[(32'h0)+:(63)];
                    end
                2:
                    begin
                        exit_plane$d = head[(32'h0)+:(63)];
                    end
                3:
                    begin
                        mant_xy$d = head[(32'h0)+:(50)];
                        shift_xy$d = head[(32'h32)+:(12)];
                    end
                4:
                    begin
                        t_min$d = head[(32'h0)+:(32)];
                        t_max$d = head[(32'h20)+:(32)];
                    end
                default:
                    begin
                        mant_z$d = head[(32'h0)+:(25)];
                        shift_z$d = head[(32'h19)+:(6)];
                        word_index$d = 32'h0;
                        if (head[(32'h38)+:(8)] == magic) begin
                            item_ready$d = 1'b1;
                        end
                        else begin
                            refused$d = 1'b1;
                            state$d = UnitState$Finish;
                        end
                    end
            endcase
        end
        if (lane_valid & ((state$q == UnitState$Run) | (state$q == UnitState$Finish))) begin
            result_fifo$write = 1'b1;
        end
        if (accepted & cmd_write$q) begin
            written$d = written$q + 32'h1;
            in_flight_n = in_flight_n - 32'h1;
        end
        if (cmd_free & ((state$q == UnitState$Run) | (state$q == UnitState$Finish))) begin
            if (~result_fifo$empty) begin
                cmd_write$d = 1'b1;
                cmd_addr$d = result_addr$q;
                cmd_burst$d = 32'h1;
                cmd_data$d = result_fifo$data_out;
                result_fifo$read = 1'b1;
                result_addr$d = result_addr$q + 32'h1;
            end
            else if ((state$q == UnitState$Run) & more_to_read & room_to_read & ~|stale$q) begin
                cmd_read$d = 1'b1;
                cmd_addr$d = work_addr$q;
                cmd_burst$d = item_words_burst;
                work_addr$d = work_addr$q + item_words_addr;
                requested$d = requested$q + 32'h1;
                reserved_n = reserved_n + item_words_count;
            end
        end
        if (((state$q == UnitState$Run) | (state$q == UnitState$Finish)) & timed_out) begin
            cmd_read$d = 1'b0;
            cmd_write$d = 1'b0;
            timeout_pulse$d = 1'b1;
            done_pulse$d = 1'b1;
            bad_pulse$d = 1'b0;
            state$d = UnitState$Idle;
        end
        if (state$q == UnitState$Idle) begin
            watchdog$d = 32'h0;
        end
        reserved$d = reserved_n;
        in_flight$d = in_flight_n;
        status_busy = state$q != UnitState$Idle;
        status_done_set = done_pulse$q;
        status_bad_descriptor_set = bad_pulse$q;
        status_out_of_window_set = window_pulse$q;
        status_bus_timeout_set = timeout_pulse$q;
        tests_done_count = ((written$q) & 32'hffffffff);
        info_lanes = lanes_value;
        rbx_address = cmd_addr$q;
        rbx_burstcount = cmd_burst$q;
        rbx_read = cmd_read$q;
        rbx_write = cmd_write$q;
        rbx_writedata = cmd_data$q;
        rbx_byteenable = 32'hff;
    end
    
endmodule // skylux_core$raybox


module skylux_core$raybox$bad_pulse(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$bad_pulse


module skylux_core$raybox$base_result(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$base_result


module skylux_core$raybox$base_work(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$base_work


module skylux_core$raybox$cmd_addr(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$cmd_addr


module skylux_core$raybox$cmd_burst(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$cmd_burst


module skylux_core$raybox$cmd_data(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$cmd_data


module skylux_core$raybox$cmd_read(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$cmd_read


module skylux_core$raybox$cmd_write(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$cmd_write


module skylux_core$raybox$count(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$count


module skylux_core$raybox$done_pulse(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$done_pulse


module skylux_core$raybox$entry_plane(d,q,clock);
    
    // Module arguments
    input wire  [62:0] d;
    output reg  [62:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 63'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$entry_plane


module skylux_core$raybox$exit_plane(d,q,clock);
    
    // Module arguments
    input wire  [62:0] d;
    output reg  [62:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 63'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$exit_plane


module skylux_core$raybox$in_flight(d,q,clock);
    
    // Module arguments
    input wire  [4:0] d;
    output reg  [4:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 5'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$in_flight


module skylux_core$raybox$issued(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$issued


module skylux_core$raybox$item_ready(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$item_ready


module skylux_core$raybox$lane_select(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lane_select


module skylux_core$raybox$lanes$0(clock,in_valid,in_index,origin,entry_plane,exit_plane,mant,shift,t_min,t_max,out_valid,out_index,out_hit,out_t_near);
    
    // Module arguments
    input wire  clock;
    input wire  in_valid;
    input wire  [23:0] in_index;
    input wire  [62:0] origin;
    input wire  [62:0] entry_plane;
    input wire  [62:0] exit_plane;
    input wire  [74:0] mant;
    input wire  [17:0] shift;
    input wire  [31:0] t_min;
    input wire  [31:0] t_max;
    output reg  out_valid;
    output reg  [23:0] out_index;
    output reg  out_hit;
    output reg  [31:0] out_t_near;
    
    // Constant declarations
    localparam  sign = 32'h80000000;
    
    // Stub signals
    reg  [20:0] entry_mul$0$plane;
    reg  [20:0] entry_mul$0$origin;
    reg  [24:0] entry_mul$0$mant;
    wire  [47:0] entry_mul$0$product;
    reg  [20:0] entry_mul$1$plane;
    reg  [20:0] entry_mul$1$origin;
    reg  [24:0] entry_mul$1$mant;
    wire  [47:0] entry_mul$1$product;
    reg  [20:0] entry_mul$2$plane;
    reg  [20:0] entry_mul$2$origin;
    reg  [24:0] entry_mul$2$mant;
    wire  [47:0] entry_mul$2$product;
    reg  [20:0] exit_mul$0$plane;
    reg  [20:0] exit_mul$0$origin;
    reg  [24:0] exit_mul$0$mant;
    wire  [47:0] exit_mul$0$product;
    reg  [20:0] exit_mul$1$plane;
    reg  [20:0] exit_mul$1$origin;
    reg  [24:0] exit_mul$1$mant;
    wire  [47:0] exit_mul$1$product;
    reg  [20:0] exit_mul$2$plane;
    reg  [20:0] exit_mul$2$origin;
    reg  [24:0] exit_mul$2$mant;
    wire  [47:0] exit_mul$2$product;
    reg  [47:0] entry_dist$0$product;
    reg  [5:0] entry_dist$0$shift;
    wire  [31:0] entry_dist$0$t;
    reg  [47:0] entry_dist$1$product;
    reg  [5:0] entry_dist$1$shift;
    wire  [31:0] entry_dist$1$t;
    reg  [47:0] entry_dist$2$product;
    reg  [5:0] entry_dist$2$shift;
    wire  [31:0] entry_dist$2$t;
    reg  [47:0] exit_dist$0$product;
    reg  [5:0] exit_dist$0$shift;
    wire  [31:0] exit_dist$0$t;
    reg  [47:0] exit_dist$1$product;
    reg  [5:0] exit_dist$1$shift;
    wire  [31:0] exit_dist$1$t;
    reg  [47:0] exit_dist$2$product;
    reg  [5:0] exit_dist$2$shift;
    wire  [31:0] exit_dist$2$t;
    reg  [20:0] s1_origin$0$d;
    wire  [20:0] s1_origin$0$q;
    reg  s1_origin$0$clock;
    reg  [20:0] s1_origin$1$d;
    wire  [20:0] s1_origin$1$q;
    reg  s1_origin$1$clock;
    reg  [20:0] s1_origin$2$d;
    wire  [20:0] s1_origin$2$q;
    reg  s1_origin$2$clock;
    reg  [20:0] s1_entry$0$d;
    wire  [20:0] s1_entry$0$q;
    reg  s1_entry$0$clock;
    reg  [20:0] s1_entry$1$d;
    wire  [20:0] s1_entry$1$q;
    reg  s1_entry$1$clock;
    reg  [20:0] s1_entry$2$d;
    wire  [20:0] s1_entry$2$q;
    reg  s1_entry$2$clock;
    reg  [20:0] s1_exit$0$d;
    wire  [20:0] s1_exit$0$q;
    reg  s1_exit$0$clock;
    reg  [20:0] s1_exit$1$d;
    wire  [20:0] s1_exit$1$q;
    reg  s1_exit$1$clock;
    reg  [20:0] s1_exit$2$d;
    wire  [20:0] s1_exit$2$q;
    reg  s1_exit$2$clock;
    reg  [24:0] s1_mant$0$d;
    wire  [24:0] s1_mant$0$q;
    reg  s1_mant$0$clock;
    reg  [24:0] s1_mant$1$d;
    wire  [24:0] s1_mant$1$q;
    reg  s1_mant$1$clock;
    reg  [24:0] s1_mant$2$d;
    wire  [24:0] s1_mant$2$q;
    reg  s1_mant$2$clock;
    reg  [5:0] s1_shift$0$d;
    wire  [5:0] s1_shift$0$q;
    reg  s1_shift$0$clock;
    reg  [5:0] s1_shift$1$d;
    wire  [5:0] s1_shift$1$q;
    reg  s1_shift$1$clock;
    reg  [5:0] s1_shift$2$d;
    wire  [5:0] s1_shift$2$q;
    reg  s1_shift$2$clock;
    reg  [31:0] s1_t_min$d;
    wire  [31:0] s1_t_min$q;
    reg  s1_t_min$clock;
    reg  [31:0] s1_t_max$d;
    wire  [31:0] s1_t_max$q;
    reg  s1_t_max$clock;
    reg  s1_valid$d;
    wire  s1_valid$q;
    reg  s1_valid$clock;
    reg  [23:0] s1_index$d;
    wire  [23:0] s1_index$q;
    reg  s1_index$clock;
    reg  [47:0] s2_entry$0$d;
    wire  [47:0] s2_entry$0$q;
    reg  s2_entry$0$clock;
    reg  [47:0] s2_entry$1$d;
    wire  [47:0] s2_entry$1$q;
    reg  s2_entry$1$clock;
    reg  [47:0] s2_entry$2$d;
    wire  [47:0] s2_entry$2$q;
    reg  s2_entry$2$clock;
    reg  [47:0] s2_exit$0$d;
    wire  [47:0] s2_exit$0$q;
    reg  s2_exit$0$clock;
    reg  [47:0] s2_exit$1$d;
    wire  [47:0] s2_exit$1$q;
    reg  s2_exit$1$clock;
    reg  [47:0] s2_exit$2$d;
    wire  [47:0] s2_exit$2$q;
    reg  s2_exit$2$clock;
    reg  [5:0] s2_shift$0$d;
    wire  [5:0] s2_shift$0$q;
    reg  s2_shift$0$clock;
    reg  [5:0] s2_shift$1$d;
    wire  [5:0] s2_shift$1$q;
    reg  s2_shift$1$clock;
    reg  [5:0] s2_shift$2$d;
    wire  [5:0] s2_shift$2$q;
    reg  s2_shift$2$clock;
    reg  [31:0] s2_t_min$d;
    wire  [31:0] s2_t_min$q;
    reg  s2_t_min$clock;
    reg  [31:0] s2_t_max$d;
    wire  [31:0] s2_t_max$q;
    reg  s2_t_max$clock;
    reg  s2_valid$d;
    wire  s2_valid$q;
    reg  s2_valid$clock;
    reg  [23:0] s2_index$d;
    wire  [23:0] s2_index$q;
    reg  s2_index$clock;
    reg  [31:0] s3_entry$0$d;
    wire  [31:0] s3_entry$0$q;
    reg  s3_entry$0$clock;
    reg  [31:0] s3_entry$1$d;
    wire  [31:0] s3_entry$1$q;
    reg  s3_entry$1$clock;
    reg  [31:0] s3_entry$2$d;
    wire  [31:0] s3_entry$2$q;
    reg  s3_entry$2$clock;
    reg  [31:0] s3_exit$0$d;
    wire  [31:0] s3_exit$0$q;
    reg  s3_exit$0$clock;
    reg  [31:0] s3_exit$1$d;
    wire  [31:0] s3_exit$1$q;
    reg  s3_exit$1$clock;
    reg  [31:0] s3_exit$2$d;
    wire  [31:0] s3_exit$2$q;
    reg  s3_exit$2$clock;
    reg  [31:0] s3_t_min$d;
    wire  [31:0] s3_t_min$q;
    reg  s3_t_min$clock;
    reg  [31:0] s3_t_max$d;
    wire  [31:0] s3_t_max$q;
    reg  s3_t_max$clock;
    reg  s3_valid$d;
    wire  s3_valid$q;
    reg  s3_valid$clock;
    reg  [23:0] s3_index$d;
    wire  [23:0] s3_index$q;
    reg  s3_index$clock;
    reg  [31:0] s4_near_xy$d;
    wire  [31:0] s4_near_xy$q;
    reg  s4_near_xy$clock;
    reg  [31:0] s4_near_z$d;
    wire  [31:0] s4_near_z$q;
    reg  s4_near_z$clock;
    reg  [31:0] s4_far_xy$d;
    wire  [31:0] s4_far_xy$q;
    reg  s4_far_xy$clock;
    reg  [31:0] s4_far_z$d;
    wire  [31:0] s4_far_z$q;
    reg  s4_far_z$clock;
    reg  s4_valid$d;
    wire  s4_valid$q;
    reg  s4_valid$clock;
    reg  [23:0] s4_index$d;
    wire  [23:0] s4_index$q;
    reg  s4_index$clock;
    reg  [31:0] s5_near$d;
    wire  [31:0] s5_near$q;
    reg  s5_near$clock;
    reg  [31:0] s5_far$d;
    wire  [31:0] s5_far$q;
    reg  s5_far$clock;
    reg  s5_valid$d;
    wire  s5_valid$q;
    reg  s5_valid$clock;
    reg  [23:0] s5_index$d;
    wire  [23:0] s5_index$q;
    reg  s5_index$clock;
    reg  s6_hit$d;
    wire  s6_hit$q;
    reg  s6_hit$clock;
    reg  [31:0] s6_near$d;
    wire  [31:0] s6_near$q;
    reg  s6_near$clock;
    reg  s6_valid$d;
    wire  s6_valid$q;
    reg  s6_valid$clock;
    reg  [23:0] s6_index$d;
    wire  [23:0] s6_index$q;
    reg  s6_index$clock;
    
    // Sub module instances
    skylux_core$raybox$lanes$0$entry_mul$0 entry_mul$0(
        .plane(entry_mul$0$plane),
        .origin(entry_mul$0$origin),
        .mant(entry_mul$0$mant),
        .product(entry_mul$0$product)
    );
    skylux_core$raybox$lanes$0$entry_mul$1 entry_mul$1(
        .plane(entry_mul$1$plane),
        .origin(entry_mul$1$origin),
        .mant(entry_mul$1$mant),
        .product(entry_mul$1$product)
    );
    skylux_core$raybox$lanes$0$entry_mul$2 entry_mul$2(
        .plane(entry_mul$2$plane),
        .origin(entry_mul$2$origin),
        .mant(entry_mul$2$mant),
        .product(entry_mul$2$product)
    );
    skylux_core$raybox$lanes$0$exit_mul$0 exit_mul$0(
        .plane(exit_mul$0$plane),
        .origin(exit_mul$0$origin),
        .mant(exit_mul$0$mant),
        .product(exit_mul$0$product)
    );
    skylux_core$raybox$lanes$0$exit_mul$1 exit_mul$1(
        .plane(exit_mul$1$plane),
        .origin(exit_mul$1$origin),
        .mant(exit_mul$1$mant),
        .product(exit_mul$1$product)
    );
    skylux_core$raybox$lanes$0$exit_mul$2 exit_mul$2(
        .plane(exit_mul$2$plane),
        .origin(exit_mul$2$origin),
        .mant(exit_mul$2$mant),
        .product(exit_mul$2$product)
    );
    skylux_core$raybox$lanes$0$entry_dist$0 entry_dist$0(
        .product(entry_dist$0$product),
        .shift(entry_dist$0$shift),
        .t(entry_dist$0$t)
    );
    skylux_core$raybox$lanes$0$entry_dist$1 entry_dist$1(
        .product(entry_dist$1$product),
        .shift(entry_dist$1$shift),
        .t(entry_dist$1$t)
    );
    skylux_core$raybox$lanes$0$entry_dist$2 entry_dist$2(
        .product(entry_dist$2$product),
        .shift(entry_dist$2$shift),
        .t(entry_dist$2$t)
    );
    skylux_core$raybox$lanes$0$exit_dist$0 exit_dist$0(
        .product(exit_dist$0$product),
        .shift(exit_dist$0$shift),
        .t(exit_dist$0$t)
    );
    skylux_core$raybox$lanes$0$exit_dist$1 exit_dist$1(
        .product(exit_dist$1$product),
        .shift(exit_dist$1$shift),
        .t(exit_dist$1$t)
    );
    skylux_core$raybox$lanes$0$exit_dist$2 exit_dist$2(
        .product(exit_dist$2$product),
        .shift(exit_dist$2$shift),
        .t(exit_dist$2$t)
    );
    skylux_core$raybox$lanes$0$s1_origin$0 s1_origin$0(
        .d(s1_origin$0$d),
        .q(s1_origin$0$q),
        .clock(s1_origin$0$clock)
    );
    skylux_core$raybox$lanes$0$s1_origin$1 s1_origin$1(
        .d(s1_origin$1$d),
        .q(s1_origin$1$q),
        .clock(s1_origin$1$clock)
    );
    skylux_core$raybox$lanes$0$s1_origin$2 s1_origin$2(
        .d(s1_origin$2$d),
        .q(s1_origin$2$q),
        .clock(s1_origin$2$clock)
    );
    skylux_core$raybox$lanes$0$s1_entry$0 s1_entry$0(
        .d(s1_entry$0$d),
        .q(s1_entry$0$q),
        .clock(s1_entry$0$clock)
    );
    skylux_core$raybox$lanes$0$s1_entry$1 s1_entry$1(
        .d(s1_entry$1$d),
        .q(s1_entry$1$q),
        .clock(s1_entry$1$clock)
    );
    skylux_core$raybox$lanes$0$s1_entry$2 s1_entry$2(
        .d(s1_entry$2$d),
        .q(s1_entry$2$q),
        .clock(s1_entry$2$clock)
    );
    skylux_core$raybox$lanes$0$s1_exit$0 s1_exit$0(
        .d(s1_exit$0$d),
        .q(s1_exit$0$q),
        .clock(s1_exit$0$clock)
    );
    skylux_core$raybox$lanes$0$s1_exit$1 s1_exit$1(
        .d(s1_exit$1$d),
        .q(s1_exit$1$q),
        .clock(s1_exit$1$clock)
    );
    skylux_core$raybox$lanes$0$s1_exit$2 s1_exit$2(
        .d(s1_exit$2$d),
        .q(s1_exit$2$q),
        .clock(s1_exit$2$clock)
    );
    skylux_core$raybox$lanes$0$s1_mant$0 s1_mant$0(
        .d(s1_mant$0$d),
        .q(s1_mant$0$q),
        .clock(s1_mant$0$clock)
    );
    skylux_core$raybox$lanes$0$s1_mant$1 s1_mant$1(
        .d(s1_mant$1$d),
        .q(s1_mant$1$q),
        .clock(s1_mant$1$clock)
    );
    skylux_core$raybox$lanes$0$s1_mant$2 s1_mant$2(
        .d(s1_mant$2$d),
        .q(s1_mant$2$q),
        .clock(s1_mant$2$clock)
    );
    skylux_core$raybox$lanes$0$s1_shift$0 s1_shift$0(
        .d(s1_shift$0$d),
        .q(s1_shift$0$q),
        .clock(s1_shift$0$clock)
    );
    skylux_core$raybox$lanes$0$s1_shift$1 s1_shift$1(
        .d(s1_shift$1$d),
        .q(s1_shift$1$q),
        .clock(s1_shift$1$clock)
    );
    skylux_core$raybox$lanes$0$s1_shift$2 s1_shift$2(
        .d(s1_shift$2$d),
        .q(s1_shift$2$q),
        .clock(s1_shift$2$clock)
    );
    skylux_core$raybox$lanes$0$s1_t_min s1_t_min(
        .d(s1_t_min$d),
        .q(s1_t_min$q),
        .clock(s1_t_min$clock)
    );
    skylux_core$raybox$lanes$0$s1_t_max s1_t_max(
        .d(s1_t_max$d),
        .q(s1_t_max$q),
        .clock(s1_t_max$clock)
    );
    skylux_core$raybox$lanes$0$s1_valid s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    skylux_core$raybox$lanes$0$s1_index s1_index(
        .d(s1_index$d),
        .q(s1_index$q),
        .clock(s1_index$clock)
    );
    skylux_core$raybox$lanes$0$s2_entry$0 s2_entry$0(
        .d(s2_entry$0$d),
        .q(s2_entry$0$q),
        .clock(s2_entry$0$clock)
    );
    skylux_core$raybox$lanes$0$s2_entry$1 s2_entry$1(
        .d(s2_entry$1$d),
        .q(s2_entry$1$q),
        .clock(s2_entry$1$clock)
    );
    skylux_core$raybox$lanes$0$s2_entry$2 s2_entry$2(
        .d(s2_entry$2$d),
        .q(s2_entry$2$q),
        .clock(s2_entry$2$clock)
    );
    skylux_core$raybox$lanes$0$s2_exit$0 s2_exit$0(
        .d(s2_exit$0$d),
        .q(s2_exit$0$q),
        .clock(s2_exit$0$clock)
    );
    skylux_core$raybox$lanes$0$s2_exit$1 s2_exit$1(
        .d(s2_exit$1$d),
        .q(s2_exit$1$q),
        .clock(s2_exit$1$clock)
    );
    skylux_core$raybox$lanes$0$s2_exit$2 s2_exit$2(
        .d(s2_exit$2$d),
        .q(s2_exit$2$q),
        .clock(s2_exit$2$clock)
    );
    skylux_core$raybox$lanes$0$s2_shift$0 s2_shift$0(
        .d(s2_shift$0$d),
        .q(s2_shift$0$q),
        .clock(s2_shift$0$clock)
    );
    skylux_core$raybox$lanes$0$s2_shift$1 s2_shift$1(
        .d(s2_shift$1$d),
        .q(s2_shift$1$q),
        .clock(s2_shift$1$clock)
    );
    skylux_core$raybox$lanes$0$s2_shift$2 s2_shift$2(
        .d(s2_shift$2$d),
        .q(s2_shift$2$q),
        .clock(s2_shift$2$clock)
    );
    skylux_core$raybox$lanes$0$s2_t_min s2_t_min(
        .d(s2_t_min$d),
        .q(s2_t_min$q),
        .clock(s2_t_min$clock)
    );
    skylux_core$raybox$lanes$0$s2_t_max s2_t_max(
        .d(s2_t_max$d),
        .q(s2_t_max$q),
        .clock(s2_t_max$clock)
    );
    skylux_core$raybox$lanes$0$s2_valid s2_valid(
        .d(s2_valid$d),
        .q(s2_valid$q),
        .clock(s2_valid$clock)
    );
    skylux_core$raybox$lanes$0$s2_index s2_index(
        .d(s2_index$d),
        .q(s2_index$q),
        .clock(s2_index$clock)
    );
    skylux_core$raybox$lanes$0$s3_entry$0 s3_entry$0(
        .d(s3_entry$0$d),
        .q(s3_entry$0$q),
        .clock(s3_entry$0$clock)
    );
    skylux_core$raybox$lanes$0$s3_entry$1 s3_entry$1(
        .d(s3_entry$1$d),
        .q(s3_entry$1$q),
        .clock(s3_entry$1$clock)
    );
    skylux_core$raybox$lanes$0$s3_entry$2 s3_entry$2(
        .d(s3_entry$2$d),
        .q(s3_entry$2$q),
        .clock(s3_entry$2$clock)
    );
    skylux_core$raybox$lanes$0$s3_exit$0 s3_exit$0(
        .d(s3_exit$0$d),
        .q(s3_exit$0$q),
        .clock(s3_exit$0$clock)
    );
    skylux_core$raybox$lanes$0$s3_exit$1 s3_exit$1(
        .d(s3_exit$1$d),
        .q(s3_exit$1$q),
        .clock(s3_exit$1$clock)
    );
    skylux_core$raybox$lanes$0$s3_exit$2 s3_exit$2(
        .d(s3_exit$2$d),
        .q(s3_exit$2$q),
        .clock(s3_exit$2$clock)
    );
    skylux_core$raybox$lanes$0$s3_t_min s3_t_min(
        .d(s3_t_min$d),
        .q(s3_t_min$q),
        .clock(s3_t_min$clock)
    );
    skylux_core$raybox$lanes$0$s3_t_max s3_t_max(
        .d(s3_t_max$d),
        .q(s3_t_max$q),
        .clock(s3_t_max$clock)
    );
    skylux_core$raybox$lanes$0$s3_valid s3_valid(
        .d(s3_valid$d),
        .q(s3_valid$q),
        .clock(s3_valid$clock)
    );
    skylux_core$raybox$lanes$0$s3_index s3_index(
        .d(s3_index$d),
        .q(s3_index$q),
        .clock(s3_index$clock)
    );
    skylux_core$raybox$lanes$0$s4_near_xy s4_near_xy(
        .d(s4_near_xy$d),
        .q(s4_near_xy$q),
        .clock(s4_near_xy$clock)
    );
    skylux_core$raybox$lanes$0$s4_near_z s4_near_z(
        .d(s4_near_z$d),
        .q(s4_near_z$q),
        .clock(s4_near_z$clock)
    );
    skylux_core$raybox$lanes$0$s4_far_xy s4_far_xy(
        .d(s4_far_xy$d),
        .q(s4_far_xy$q),
        .clock(s4_far_xy$clock)
    );
    skylux_core$raybox$lanes$0$s4_far_z s4_far_z(
        .d(s4_far_z$d),
        .q(s4_far_z$q),
        .clock(s4_far_z$clock)
    );
    skylux_core$raybox$lanes$0$s4_valid s4_valid(
        .d(s4_valid$d),
        .q(s4_valid$q),
        .clock(s4_valid$clock)
    );
    skylux_core$raybox$lanes$0$s4_index s4_index(
        .d(s4_index$d),
        .q(s4_index$q),
        .clock(s4_index$clock)
    );
    skylux_core$raybox$lanes$0$s5_near s5_near(
        .d(s5_near$d),
        .q(s5_near$q),
        .clock(s5_near$clock)
    );
    skylux_core$raybox$lanes$0$s5_far s5_far(
        .d(s5_far$d),
        .q(s5_far$q),
        .clock(s5_far$clock)
    );
    skylux_core$raybox$lanes$0$s5_valid s5_valid(
        .d(s5_valid$d),
        .q(s5_valid$q),
        .clock(s5_valid$clock)
    );
    skylux_core$raybox$lanes$0$s5_index s5_index(
        .d(s5_index$d),
        .q(s5_index$q),
        .clock(s5_index$clock)
    );
    skylux_core$raybox$lanes$0$s6_hit s6_hit(
        .d(s6_hit$d),
        .q(s6_hit$q),
        .clock(s6_hit$clock)
    );
    skylux_core$raybox$lanes$0$s6_near s6_near(
        .d(s6_near$d),
        .q(s6_near$q),
        .clock(s6_near$clock)
    );
    skylux_core$raybox$lanes$0$s6_valid s6_valid(
        .d(s6_valid$d),
        .q(s6_valid$q),
        .clock(s6_valid$clock)
    );
    skylux_core$raybox$lanes$0$s6_index s6_index(
        .d(s6_index$d),
        .q(s6_index$q),
        .clock(s6_index$clock)
    );
    
    // Update code
    always @(*) begin
        s1_t_min$clock = clock;
        s1_t_max$clock = clock;
        s1_valid$clock = clock;
        s1_index$clock = clock;
        s2_t_min$clock = clock;
        s2_t_max$clock = clock;
        s2_valid$clock = clock;
        s2_index$clock = clock;
        s3_t_min$clock = clock;
        s3_t_max$clock = clock;
        s3_valid$clock = clock;
        s3_index$clock = clock;
        s4_near_xy$clock = clock;
        s4_near_z$clock = clock;
        s4_far_xy$clock = clock;
        s4_far_z$clock = clock;
        s4_valid$clock = clock;
        s4_index$clock = clock;
        s5_near$clock = clock;
        s5_far$clock = clock;
        s5_valid$clock = clock;
        s5_index$clock = clock;
        s6_hit$clock = clock;
        s6_near$clock = clock;
        s6_valid$clock = clock;
        s6_index$clock = clock;
        s1_t_min$d = s1_t_min$q;
        s1_t_max$d = s1_t_max$q;
        s1_valid$d = s1_valid$q;
        s1_index$d = s1_index$q;
        s2_t_min$d = s2_t_min$q;
        s2_t_max$d = s2_t_max$q;
        s2_valid$d = s2_valid$q;
        s2_index$d = s2_index$q;
        s3_t_min$d = s3_t_min$q;
        s3_t_max$d = s3_t_max$q;
        s3_valid$d = s3_valid$q;
        s3_index$d = s3_index$q;
        s4_near_xy$d = s4_near_xy$q;
        s4_near_z$d = s4_near_z$q;
        s4_far_xy$d = s4_far_xy$q;
        s4_far_z$d = s4_far_z$q;
        s4_valid$d = s4_valid$q;
        s4_index$d = s4_index$q;
        s5_near$d = s5_near$q;
        s5_far$d = s5_far$q;
        s5_valid$d = s5_valid$q;
        s5_index$d = s5_index$q;
        s6_hit$d = s6_hit$q;
        s6_near$d = s6_near$q;
        s6_valid$d = s6_valid$q;
        s6_index$d = s6_index$q;
        s1_origin$0$clock = clock;
        s1_entry$0$clock = clock;
        s1_exit$0$clock = clock;
        s1_mant$0$clock = clock;
        s1_shift$0$clock = clock;
        s2_entry$0$clock = clock;
        s2_exit$0$clock = clock;
        s2_shift$0$clock = clock;
        s3_entry$0$clock = clock;
        s3_exit$0$clock = clock;
        entry_mul$0$plane = s1_entry$0$q;
        entry_mul$0$origin = s1_origin$0$q;
        entry_mul$0$mant = s1_mant$0$q;
        exit_mul$0$plane = s1_exit$0$q;
        exit_mul$0$origin = s1_origin$0$q;
        exit_mul$0$mant = s1_mant$0$q;
        s2_entry$0$d = entry_mul$0$product;
        s2_exit$0$d = exit_mul$0$product;
        s2_shift$0$d = s1_shift$0$q;
        entry_dist$0$product = s2_entry$0$q;
        entry_dist$0$shift = s2_shift$0$q;
        exit_dist$0$product = s2_exit$0$q;
        exit_dist$0$shift = s2_shift$0$q;
        s3_entry$0$d = entry_dist$0$t;
        s3_exit$0$d = exit_dist$0$t;
        s1_origin$1$clock = clock;
        s1_entry$1$clock = clock;
        s1_exit$1$clock = clock;
        s1_mant$1$clock = clock;
        s1_shift$1$clock = clock;
        s2_entry$1$clock = clock;
        s2_exit$1$clock = clock;
        s2_shift$1$clock = clock;
        s3_entry$1$clock = clock;
        s3_exit$1$clock = clock;
        entry_mul$1$plane = s1_entry$1$q;
        entry_mul$1$origin = s1_origin$1$q;
        entry_mul$1$mant = s1_mant$1$q;
        exit_mul$1$plane = s1_exit$1$q;
        exit_mul$1$origin = s1_origin$1$q;
        exit_mul$1$mant = s1_mant$1$q;
        s2_entry$1$d = entry_mul$1$product;
        s2_exit$1$d = exit_mul$1$product;
        s2_shift$1$d = s1_shift$1$q;
        entry_dist$1$product = s2_entry$1$q;
        entry_dist$1$shift = s2_shift$1$q;
        exit_dist$1$product = s2_exit$1$q;
        exit_dist$1$shift = s2_shift$1$q;
        s3_entry$1$d = entry_dist$1$t;
        s3_exit$1$d = exit_dist$1$t;
        s1_origin$2$clock = clock;
        s1_entry$2$clock = clock;
        s1_exit$2$clock = clock;
        s1_mant$2$clock = clock;
        s1_shift$2$clock = clock;
        s2_entry$2$clock = clock;
        s2_exit$2$clock = clock;
        s2_shift$2$clock = clock;
        s3_entry$2$clock = clock;
        s3_exit$2$clock = clock;
        entry_mul$2$plane = s1_entry$2$q;
        entry_mul$2$origin = s1_origin$2$q;
        entry_mul$2$mant = s1_mant$2$q;
        exit_mul$2$plane = s1_exit$2$q;
        exit_mul$2$origin = s1_origin$2$q;
        exit_mul$2$mant = s1_mant$2$q;
        s2_entry$2$d = entry_mul$2$product;
        s2_exit$2$d = exit_mul$2$product;
        s2_shift$2$d = s1_shift$2$q;
        entry_dist$2$product = s2_entry$2$q;
        entry_dist$2$shift = s2_shift$2$q;
        exit_dist$2$product = s2_exit$2$q;
        exit_dist$2$shift = s2_shift$2$q;
        s3_entry$2$d = entry_dist$2$t;
        s3_exit$2$d = exit_dist$2$t;
        s1_origin$0$d = origin[(32'h0)+:(21)];
        s1_origin$1$d = origin[(32'h15)+:(21)];
        s1_origin$2$d = origin[(32'h2a)+:(21)];
        s1_entry$0$d = entry_plane[(32'h0)+:(21)];
        s1_entry$1$d = entry_plane[(32'h15)+:(21)];
        s1_entry$2$d = entry_plane[(32'h2a)+:(21)];
        s1_exit$0$d = exit_plane[(32'h0)+:(21)];
        s1_exit$1$d = exit_plane[(32'h15)+:(21)];
        s1_exit$2$d = exit_plane[(32'h2a)+:(21)];
        s1_mant$0$d = mant[(32'h0)+:(25)];
        s1_mant$1$d = mant[(32'h19)+:(25)];
        s1_mant$2$d = mant[(32'h32)+:(25)];
        s1_shift$0$d = shift[(32'h0)+:(6)];
        s1_shift$1$d = shift[(32'h6)+:(6)];
        s1_shift$2$d = shift[(32'hc)+:(6)];
        s1_t_min$d = t_min;
        s1_t_max$d = t_max;
        s1_valid$d = in_valid;
        s1_index$d = in_index;
        s2_t_min$d = s1_t_min$q;
        s2_t_max$d = s1_t_max$q;
        s2_valid$d = s1_valid$q;
        s2_index$d = s1_index$q;
        s3_t_min$d = s2_t_min$q;
        s3_t_max$d = s2_t_max$q;
        s3_valid$d = s2_valid$q;
        s3_index$d = s2_index$q;
        s4_near_xy$d = s3_entry$0$q;
        if ((s3_entry$1$q ^ sign) > (s3_entry$0$q ^ sign)) begin
            s4_near_xy$d = s3_entry$1$q;
        end
        s4_near_z$d = s3_t_min$q;
        if ((s3_entry$2$q ^ sign) > (s3_t_min$q ^ sign)) begin
            s4_near_z$d = s3_entry$2$q;
        end
        s4_far_xy$d = s3_exit$0$q;
        if ((s3_exit$1$q ^ sign) < (s3_exit$0$q ^ sign)) begin
            s4_far_xy$d = s3_exit$1$q;
        end
        s4_far_z$d = s3_t_max$q;
        if ((s3_exit$2$q ^ sign) < (s3_t_max$q ^ sign)) begin
            s4_far_z$d = s3_exit$2$q;
        end
        s4_valid$d = s3_valid$q;
        s4_index$d = s3_index$q;
        s5_near$d = s4_near_xy$q;
        if ((s4_near_z$q ^ sign) > (s4_near_xy$q ^ sign)) begin
            s5_near$d = s4_near_z$q;
        end
        s5_far$d = s4_far_xy$q;
        if ((s4_far_z$q ^ sign) < (s4_far_xy$q ^ sign)) begin
            s5_far$d = s4_far_z$q;
        end
        s5_valid$d = s4_valid$q;
        s5_index$d = s4_index$q;
        s6_hit$d = (s5_near$q ^ sign) <= (s5_far$q ^ sign);
        s6_near$d = s5_near$q;
        s6_valid$d = s5_valid$q;
        s6_index$d = s5_index$q;
        out_valid = s6_valid$q;
        out_index = s6_index$q;
        out_hit = s6_hit$q;
        out_t_near = s6_near$q;
    end
    
endmodule // skylux_core$raybox$lanes$0


module skylux_core$raybox$lanes$0$entry_dist$0(product,shift,t);
    
    // Module arguments
    input wire  [47:0] product;
    input wire  [5:0] shift;
    output reg  [31:0] t;
    
    // Update code (custom)
    wire signed [47:0] q = $signed(product) >>> shift;
    always @(*) begin
      if (q > $signed(48'h7fffffff)) t = 32'h7fffffff;
      else if (q < -$signed(48'h80000000)) t = 32'h80000000;
      else t = q[31:0];
    end
endmodule // skylux_core$raybox$lanes$0$entry_dist$0


module skylux_core$raybox$lanes$0$entry_dist$1(product,shift,t);
    
    // Module arguments
    input wire  [47:0] product;
    input wire  [5:0] shift;
    output reg  [31:0] t;
    
    // Update code (custom)
    wire signed [47:0] q = $signed(product) >>> shift;
    always @(*) begin
      if (q > $signed(48'h7fffffff)) t = 32'h7fffffff;
      else if (q < -$signed(48'h80000000)) t = 32'h80000000;
      else t = q[31:0];
    end
endmodule // skylux_core$raybox$lanes$0$entry_dist$1


module skylux_core$raybox$lanes$0$entry_dist$2(product,shift,t);
    
    // Module arguments
    input wire  [47:0] product;
    input wire  [5:0] shift;
    output reg  [31:0] t;
    
    // Update code (custom)
    wire signed [47:0] q = $signed(product) >>> shift;
    always @(*) begin
      if (q > $signed(48'h7fffffff)) t = 32'h7fffffff;
      else if (q < -$signed(48'h80000000)) t = 32'h80000000;
      else t = q[31:0];
    end
endmodule // skylux_core$raybox$lanes$0$entry_dist$2


module skylux_core$raybox$lanes$0$entry_mul$0(plane,origin,mant,product);
    
    // Module arguments
    input wire  [20:0] plane;
    input wire  [20:0] origin;
    input wire  [24:0] mant;
    output reg  [47:0] product;
    
    // Update code (custom)
    wire signed [21:0] diff = $signed(plane) - $signed(origin);
    wire signed [47:0] full = diff * $signed(mant);
    always @(*) product = full;
endmodule // skylux_core$raybox$lanes$0$entry_mul$0


module skylux_core$raybox$lanes$0$entry_mul$1(plane,origin,mant,product);
    
    // Module arguments
    input wire  [20:0] plane;
    input wire  [20:0] origin;
    input wire  [24:0] mant;
    output reg  [47:0] product;
    
    // Update code (custom)
    wire signed [21:0] diff = $signed(plane) - $signed(origin);
    wire signed [47:0] full = diff * $signed(mant);
    always @(*) product = full;
endmodule // skylux_core$raybox$lanes$0$entry_mul$1


module skylux_core$raybox$lanes$0$entry_mul$2(plane,origin,mant,product);
    
    // Module arguments
    input wire  [20:0] plane;
    input wire  [20:0] origin;
    input wire  [24:0] mant;
    output reg  [47:0] product;
    
    // Update code (custom)
    wire signed [21:0] diff = $signed(plane) - $signed(origin);
    wire signed [47:0] full = diff * $signed(mant);
    always @(*) product = full;
endmodule // skylux_core$raybox$lanes$0$entry_mul$2


module skylux_core$raybox$lanes$0$exit_dist$0(product,shift,t);
    
    // Module arguments
    input wire  [47:0] product;
    input wire  [5:0] shift;
    output reg  [31:0] t;
    
    // Update code (custom)
    wire signed [47:0] q = -((-$signed(product)) >>> shift);
    always @(*) begin
      if (q > $signed(48'h7fffffff)) t = 32'h7fffffff;
      else if (q < -$signed(48'h80000000)) t = 32'h80000000;
      else t = q[31:0];
    end
endmodule // skylux_core$raybox$lanes$0$exit_dist$0


module skylux_core$raybox$lanes$0$exit_dist$1(product,shift,t);
    
    // Module arguments
    input wire  [47:0] product;
    input wire  [5:0] shift;
    output reg  [31:0] t;
    
    // Update code (custom)
    wire signed [47:0] q = -((-$signed(product)) >>> shift);
    always @(*) begin
      if (q > $signed(48'h7fffffff)) t = 32'h7fffffff;
      else if (q < -$signed(48'h80000000)) t = 32'h80000000;
      else t = q[31:0];
    end
endmodule // skylux_core$raybox$lanes$0$exit_dist$1


module skylux_core$raybox$lanes$0$exit_dist$2(product,shift,t);
    
    // Module arguments
    input wire  [47:0] product;
    input wire  [5:0] shift;
    output reg  [31:0] t;
    
    // Update code (custom)
    wire signed [47:0] q = -((-$signed(product)) >>> shift);
    always @(*) begin
      if (q > $signed(48'h7fffffff)) t = 32'h7fffffff;
      else if (q < -$signed(48'h80000000)) t = 32'h80000000;
      else t = q[31:0];
    end
endmodule // skylux_core$raybox$lanes$0$exit_dist$2


module skylux_core$raybox$lanes$0$exit_mul$0(plane,origin,mant,product);
    
    // Module arguments
    input wire  [20:0] plane;
    input wire  [20:0] origin;
    input wire  [24:0] mant;
    output reg  [47:0] product;
    
    // Update code (custom)
    wire signed [21:0] diff = $signed(plane) - $signed(origin);
    wire signed [47:0] full = diff * $signed(mant);
    always @(*) product = full;
endmodule // skylux_core$raybox$lanes$0$exit_mul$0


module skylux_core$raybox$lanes$0$exit_mul$1(plane,origin,mant,product);
    
    // Module arguments
    input wire  [20:0] plane;
    input wire  [20:0] origin;
    input wire  [24:0] mant;
    output reg  [47:0] product;
    
    // Update code (custom)
    wire signed [21:0] diff = $signed(plane) - $signed(origin);
    wire signed [47:0] full = diff * $signed(mant);
    always @(*) product = full;
endmodule // skylux_core$raybox$lanes$0$exit_mul$1


module skylux_core$raybox$lanes$0$exit_mul$2(plane,origin,mant,product);
    
    // Module arguments
    input wire  [20:0] plane;
    input wire  [20:0] origin;
    input wire  [24:0] mant;
    output reg  [47:0] product;
    
    // Update code (custom)
    wire signed [21:0] diff = $signed(plane) - $signed(origin);
    wire signed [47:0] full = diff * $signed(mant);
    always @(*) product = full;
endmodule // skylux_core$raybox$lanes$0$exit_mul$2


module skylux_core$raybox$lanes$0$s1_entry$0(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s1_entry$0


module skylux_core$raybox$lanes$0$s1_entry$1(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s1_entry$1


module skylux_core$raybox$lanes$0$s1_entry$2(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s1_entry$2


module skylux_core$raybox$lanes$0$s1_exit$0(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s1_exit$0


module skylux_core$raybox$lanes$0$s1_exit$1(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s1_exit$1


module skylux_core$raybox$lanes$0$s1_exit$2(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s1_exit$2


module skylux_core$raybox$lanes$0$s1_index(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s1_index


module skylux_core$raybox$lanes$0$s1_mant$0(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s1_mant$0


module skylux_core$raybox$lanes$0$s1_mant$1(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s1_mant$1


module skylux_core$raybox$lanes$0$s1_mant$2(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s1_mant$2


module skylux_core$raybox$lanes$0$s1_origin$0(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s1_origin$0


module skylux_core$raybox$lanes$0$s1_origin$1(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s1_origin$1


module skylux_core$raybox$lanes$0$s1_origin$2(d,q,clock);
    
    // Module arguments
    input wire  [20:0] d;
    output reg  [20:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 21'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s1_origin$2


module skylux_core$raybox$lanes$0$s1_shift$0(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s1_shift$0


module skylux_core$raybox$lanes$0$s1_shift$1(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s1_shift$1


module skylux_core$raybox$lanes$0$s1_shift$2(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s1_shift$2


module skylux_core$raybox$lanes$0$s1_t_max(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s1_t_max


module skylux_core$raybox$lanes$0$s1_t_min(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s1_t_min


module skylux_core$raybox$lanes$0$s1_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s1_valid


module skylux_core$raybox$lanes$0$s2_entry$0(d,q,clock);
    
    // Module arguments
    input wire  [47:0] d;
    output reg  [47:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 48'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s2_entry$0


module skylux_core$raybox$lanes$0$s2_entry$1(d,q,clock);
    
    // Module arguments
    input wire  [47:0] d;
    output reg  [47:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 48'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s2_entry$1


module skylux_core$raybox$lanes$0$s2_entry$2(d,q,clock);
    
    // Module arguments
    input wire  [47:0] d;
    output reg  [47:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 48'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s2_entry$2


module skylux_core$raybox$lanes$0$s2_exit$0(d,q,clock);
    
    // Module arguments
    input wire  [47:0] d;
    output reg  [47:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 48'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s2_exit$0


module skylux_core$raybox$lanes$0$s2_exit$1(d,q,clock);
    
    // Module arguments
    input wire  [47:0] d;
    output reg  [47:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 48'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s2_exit$1


module skylux_core$raybox$lanes$0$s2_exit$2(d,q,clock);
    
    // Module arguments
    input wire  [47:0] d;
    output reg  [47:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 48'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s2_exit$2


module skylux_core$raybox$lanes$0$s2_index(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s2_index


module skylux_core$raybox$lanes$0$s2_shift$0(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s2_shift$0


module skylux_core$raybox$lanes$0$s2_shift$1(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s2_shift$1


module skylux_core$raybox$lanes$0$s2_shift$2(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s2_shift$2


module skylux_core$raybox$lanes$0$s2_t_max(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s2_t_max


module skylux_core$raybox$lanes$0$s2_t_min(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s2_t_min


module skylux_core$raybox$lanes$0$s2_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s2_valid


module skylux_core$raybox$lanes$0$s3_entry$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s3_entry$0


module skylux_core$raybox$lanes$0$s3_entry$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s3_entry$1


module skylux_core$raybox$lanes$0$s3_entry$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s3_entry$2


module skylux_core$raybox$lanes$0$s3_exit$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s3_exit$0


module skylux_core$raybox$lanes$0$s3_exit$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s3_exit$1


module skylux_core$raybox$lanes$0$s3_exit$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s3_exit$2


module skylux_core$raybox$lanes$0$s3_index(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s3_index


module skylux_core$raybox$lanes$0$s3_t_max(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s3_t_max


module skylux_core$raybox$lanes$0$s3_t_min(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s3_t_min


module skylux_core$raybox$lanes$0$s3_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s3_valid


module skylux_core$raybox$lanes$0$s4_far_xy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s4_far_xy


module skylux_core$raybox$lanes$0$s4_far_z(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s4_far_z


module skylux_core$raybox$lanes$0$s4_index(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s4_index


module skylux_core$raybox$lanes$0$s4_near_xy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s4_near_xy


module skylux_core$raybox$lanes$0$s4_near_z(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s4_near_z


module skylux_core$raybox$lanes$0$s4_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s4_valid


module skylux_core$raybox$lanes$0$s5_far(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s5_far


module skylux_core$raybox$lanes$0$s5_index(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s5_index


module skylux_core$raybox$lanes$0$s5_near(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s5_near


module skylux_core$raybox$lanes$0$s5_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s5_valid


module skylux_core$raybox$lanes$0$s6_hit(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s6_hit


module skylux_core$raybox$lanes$0$s6_index(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s6_index


module skylux_core$raybox$lanes$0$s6_near(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s6_near


module skylux_core$raybox$lanes$0$s6_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$lanes$0$s6_valid


module skylux_core$raybox$mant_xy(d,q,clock);
    
    // Module arguments
    input wire  [49:0] d;
    output reg  [49:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 50'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$mant_xy


module skylux_core$raybox$mant_z(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$mant_z


module skylux_core$raybox$origin(d,q,clock);
    
    // Module arguments
    input wire  [62:0] d;
    output reg  [62:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 63'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$origin


module skylux_core$raybox$outstanding(d,q,clock);
    
    // Module arguments
    input wire  [4:0] d;
    output reg  [4:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 5'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$outstanding


module skylux_core$raybox$read_fifo(clock,read,data_out,empty,almost_empty,underflow,write,data_in,full,almost_full,overflow);
    
    // Module arguments
    input wire  clock;
    input wire  read;
    output reg  [63:0] data_out;
    output reg  empty;
    output reg  almost_empty;
    output reg  underflow;
    input wire  write;
    input wire  [63:0] data_in;
    output reg  full;
    output reg  almost_full;
    output reg  overflow;
    
    // Stub signals
    reg  [3:0] ram$read_address;
    reg  ram$read_clock;
    wire  [63:0] ram$read_data;
    reg  [3:0] ram$write_address;
    reg  ram$write_clock;
    reg  [63:0] ram$write_data;
    reg  ram$write_enable;
    reg  read_logic$clock;
    reg  read_logic$read;
    wire  [63:0] read_logic$data_out;
    wire  read_logic$empty;
    wire  read_logic$almost_empty;
    wire  read_logic$underflow;
    reg  [4:0] read_logic$write_address_delayed;
    wire  [3:0] read_logic$ram_read_address;
    reg  [63:0] read_logic$ram_read_data;
    wire  read_logic$ram_read_clock;
    wire  [4:0] read_logic$read_address_out;
    wire  [4:0] read_logic$fill_level;
    reg  write_logic$write;
    reg  [63:0] write_logic$data_in;
    wire  write_logic$full;
    wire  write_logic$almost_full;
    wire  write_logic$overflow;
    reg  write_logic$clock;
    wire  [3:0] write_logic$ram_write_address;
    wire  write_logic$ram_write_clock;
    wire  [63:0] write_logic$ram_write_data;
    wire  write_logic$ram_write_enable;
    reg  [4:0] write_logic$read_address;
    wire  [4:0] write_logic$write_address_delayed;
    wire  [4:0] write_logic$fill_level;
    
    // Sub module instances
    skylux_core$raybox$read_fifo$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    skylux_core$raybox$read_fifo$read_logic read_logic(
        .clock(read_logic$clock),
        .read(read_logic$read),
        .data_out(read_logic$data_out),
        .empty(read_logic$empty),
        .almost_empty(read_logic$almost_empty),
        .underflow(read_logic$underflow),
        .write_address_delayed(read_logic$write_address_delayed),
        .ram_read_address(read_logic$ram_read_address),
        .ram_read_data(read_logic$ram_read_data),
        .ram_read_clock(read_logic$ram_read_clock),
        .read_address_out(read_logic$read_address_out),
        .fill_level(read_logic$fill_level)
    );
    skylux_core$raybox$read_fifo$write_logic write_logic(
        .write(write_logic$write),
        .data_in(write_logic$data_in),
        .full(write_logic$full),
        .almost_full(write_logic$almost_full),
        .overflow(write_logic$overflow),
        .clock(write_logic$clock),
        .ram_write_address(write_logic$ram_write_address),
        .ram_write_clock(write_logic$ram_write_clock),
        .ram_write_data(write_logic$ram_write_data),
        .ram_write_enable(write_logic$ram_write_enable),
        .read_address(write_logic$read_address),
        .write_address_delayed(write_logic$write_address_delayed),
        .fill_level(write_logic$fill_level)
    );
    
    // Update code
    always @(*) begin
        read_logic$clock = clock;
        write_logic$clock = clock;
        read_logic$read = read;
        empty = read_logic$empty;
        almost_empty = read_logic$almost_empty;
        data_out = read_logic$data_out;
        underflow = read_logic$underflow;
        overflow = write_logic$overflow;
        almost_full = write_logic$almost_full;
        full = write_logic$full;
        write_logic$write = write;
        write_logic$data_in = data_in;
        ram$write_clock = clock;
        ram$write_enable = write_logic$ram_write_enable;
        ram$write_address = write_logic$ram_write_address;
        ram$write_data = write_logic$ram_write_data;
        ram$read_clock = clock;
        ram$read_address = read_logic$ram_read_address;
        read_logic$ram_read_data = ram$read_data;
        read_logic$write_address_delayed = write_logic$write_address_delayed;
        write_logic$read_address = read_logic$read_address_out;
    end
    
endmodule // skylux_core$raybox$read_fifo


module skylux_core$raybox$read_fifo$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [3:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [3:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[63:0] mem[15:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // skylux_core$raybox$read_fifo$ram


module skylux_core$raybox$read_fifo$read_logic(clock,read,data_out,empty,almost_empty,underflow,write_address_delayed,ram_read_address,ram_read_data,ram_read_clock,read_address_out,fill_level);
    
    // Module arguments
    input wire  clock;
    input wire  read;
    output reg  [63:0] data_out;
    output reg  empty;
    output reg  almost_empty;
    output reg  underflow;
    input wire  [4:0] write_address_delayed;
    output reg  [3:0] ram_read_address;
    input wire  [63:0] ram_read_data;
    output reg  ram_read_clock;
    output reg  [4:0] read_address_out;
    output reg  [4:0] fill_level;
    
    // Constant declarations
    localparam  fifo_address_mask = 5'b1111;
    localparam  fifo_size = 5'b10000;
    localparam  block_size = 5'b1;
    
    // Stub signals
    reg  [4:0] read_address$d;
    wire  [4:0] read_address$q;
    reg  read_address$clock;
    reg  dff_underflow$d;
    wire  dff_underflow$q;
    reg  dff_underflow$clock;
    
    // Local signals
    reg  is_empty;
    reg  is_full;
    
    // Sub module instances
    skylux_core$raybox$read_fifo$read_logic$read_address read_address(
        .d(read_address$d),
        .q(read_address$q),
        .clock(read_address$clock)
    );
    skylux_core$raybox$read_fifo$read_logic$dff_underflow dff_underflow(
        .d(dff_underflow$d),
        .q(dff_underflow$q),
        .clock(dff_underflow$clock)
    );
    
    // Update code
    always @(*) begin
        read_address$clock = clock;
        dff_underflow$clock = clock;
        read_address$d = read_address$q;
        dff_underflow$d = dff_underflow$q;
        ram_read_clock = clock;
        is_empty = (read_address$q == write_address_delayed);
        is_full = ~is_empty & ((read_address$q & fifo_address_mask) == (write_address_delayed & fifo_address_mask));
        fill_level = ((write_address_delayed & fifo_address_mask) + fifo_size - (read_address$q & fifo_address_mask)) & fifo_address_mask;
        if (is_full) begin
            fill_level = fifo_size;
        end
        almost_empty = (fill_level < block_size);
        empty = is_empty;
        ram_read_address = ((read_address$q & fifo_address_mask) & 4'hf);
        data_out = ram_read_data;
        if (read & ~is_empty) begin
            read_address$d = read_address$q + 32'h1;
            ram_read_address = (((read_address$q + 32'h1) & fifo_address_mask) & 4'hf);
        end
        else begin
            read_address$d = read_address$q;
        end
        dff_underflow$d = dff_underflow$q | (is_empty & read);
        underflow = dff_underflow$q;
        read_address_out = read_address$q;
    end
    
endmodule // skylux_core$raybox$read_fifo$read_logic


module skylux_core$raybox$read_fifo$read_logic$dff_underflow(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$read_fifo$read_logic$dff_underflow


module skylux_core$raybox$read_fifo$read_logic$read_address(d,q,clock);
    
    // Module arguments
    input wire  [4:0] d;
    output reg  [4:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 5'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$read_fifo$read_logic$read_address


module skylux_core$raybox$read_fifo$write_logic(write,data_in,full,almost_full,overflow,clock,ram_write_address,ram_write_clock,ram_write_data,ram_write_enable,read_address,write_address_delayed,fill_level);
    
    // Module arguments
    input wire  write;
    input wire  [63:0] data_in;
    output reg  full;
    output reg  almost_full;
    output reg  overflow;
    input wire  clock;
    output reg  [3:0] ram_write_address;
    output reg  ram_write_clock;
    output reg  [63:0] ram_write_data;
    output reg  ram_write_enable;
    input wire  [4:0] read_address;
    output reg  [4:0] write_address_delayed;
    output reg  [4:0] fill_level;
    
    // Constant declarations
    localparam  fifo_address_mask = 5'b1111;
    localparam  fifo_size = 5'b10000;
    localparam  almost_full_level = 5'b1111;
    
    // Stub signals
    reg  [4:0] write_address$d;
    wire  [4:0] write_address$q;
    reg  write_address$clock;
    reg  [4:0] dff_write_address_delay$d;
    wire  [4:0] dff_write_address_delay$q;
    reg  dff_write_address_delay$clock;
    reg  dff_overflow$d;
    wire  dff_overflow$q;
    reg  dff_overflow$clock;
    
    // Local signals
    reg  is_empty;
    reg  is_full;
    
    // Sub module instances
    skylux_core$raybox$read_fifo$write_logic$write_address write_address(
        .d(write_address$d),
        .q(write_address$q),
        .clock(write_address$clock)
    );
    skylux_core$raybox$read_fifo$write_logic$dff_write_address_delay dff_write_address_delay(
        .d(dff_write_address_delay$d),
        .q(dff_write_address_delay$q),
        .clock(dff_write_address_delay$clock)
    );
    skylux_core$raybox$read_fifo$write_logic$dff_overflow dff_overflow(
        .d(dff_overflow$d),
        .q(dff_overflow$q),
        .clock(dff_overflow$clock)
    );
    
    // Update code
    always @(*) begin
        dff_overflow$clock = clock;
        write_address$clock = clock;
        dff_write_address_delay$clock = clock;
        dff_overflow$d = dff_overflow$q;
        write_address$d = write_address$q;
        dff_write_address_delay$d = dff_write_address_delay$q;
        ram_write_clock = clock;
        dff_write_address_delay$d = write_address$q;
        write_address_delayed = dff_write_address_delay$q;
        ram_write_enable = 1'b0;
        is_empty = (read_address == dff_write_address_delay$q);
        is_full = ~is_empty & ((read_address & fifo_address_mask) == (write_address$q & fifo_address_mask));
        fill_level = ((dff_write_address_delay$q & fifo_address_mask) + fifo_size - (read_address & fifo_address_mask)) & fifo_address_mask;
        if (is_full) begin
            fill_level = fifo_size;
        end
        almost_full = (fill_level >= almost_full_level);
        full = is_full;
        ram_write_address = ((write_address$q & fifo_address_mask) & 4'hf);
        ram_write_data = data_in;
        if (write & ~is_full) begin
            write_address$d = write_address$q + 32'h1;
            ram_write_enable = 1'b1;
        end
        else begin
            write_address$d = write_address$q;
            ram_write_enable = 1'b0;
        end
        dff_overflow$d = dff_overflow$q | (is_full & write);
        overflow = dff_overflow$q;
    end
    
endmodule // skylux_core$raybox$read_fifo$write_logic


module skylux_core$raybox$read_fifo$write_logic$dff_overflow(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$read_fifo$write_logic$dff_overflow


module skylux_core$raybox$read_fifo$write_logic$dff_write_address_delay(d,q,clock);
    
    // Module arguments
    input wire  [4:0] d;
    output reg  [4:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 5'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$read_fifo$write_logic$dff_write_address_delay


module skylux_core$raybox$read_fifo$write_logic$write_address(d,q,clock);
    
    // Module arguments
    input wire  [4:0] d;
    output reg  [4:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 5'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$read_fifo$write_logic$write_address


module skylux_core$raybox$refused(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$refused


module skylux_core$raybox$requested(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$requested


module skylux_core$raybox$reserved(d,q,clock);
    
    // Module arguments
    input wire  [4:0] d;
    output reg  [4:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 5'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$reserved


module skylux_core$raybox$result_addr(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$result_addr


module skylux_core$raybox$result_fifo(clock,read,data_out,empty,almost_empty,underflow,write,data_in,full,almost_full,overflow);
    
    // Module arguments
    input wire  clock;
    input wire  read;
    output reg  [63:0] data_out;
    output reg  empty;
    output reg  almost_empty;
    output reg  underflow;
    input wire  write;
    input wire  [63:0] data_in;
    output reg  full;
    output reg  almost_full;
    output reg  overflow;
    
    // Stub signals
    reg  [3:0] ram$read_address;
    reg  ram$read_clock;
    wire  [63:0] ram$read_data;
    reg  [3:0] ram$write_address;
    reg  ram$write_clock;
    reg  [63:0] ram$write_data;
    reg  ram$write_enable;
    reg  read_logic$clock;
    reg  read_logic$read;
    wire  [63:0] read_logic$data_out;
    wire  read_logic$empty;
    wire  read_logic$almost_empty;
    wire  read_logic$underflow;
    reg  [4:0] read_logic$write_address_delayed;
    wire  [3:0] read_logic$ram_read_address;
    reg  [63:0] read_logic$ram_read_data;
    wire  read_logic$ram_read_clock;
    wire  [4:0] read_logic$read_address_out;
    wire  [4:0] read_logic$fill_level;
    reg  write_logic$write;
    reg  [63:0] write_logic$data_in;
    wire  write_logic$full;
    wire  write_logic$almost_full;
    wire  write_logic$overflow;
    reg  write_logic$clock;
    wire  [3:0] write_logic$ram_write_address;
    wire  write_logic$ram_write_clock;
    wire  [63:0] write_logic$ram_write_data;
    wire  write_logic$ram_write_enable;
    reg  [4:0] write_logic$read_address;
    wire  [4:0] write_logic$write_address_delayed;
    wire  [4:0] write_logic$fill_level;
    
    // Sub module instances
    skylux_core$raybox$result_fifo$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    skylux_core$raybox$result_fifo$read_logic read_logic(
        .clock(read_logic$clock),
        .read(read_logic$read),
        .data_out(read_logic$data_out),
        .empty(read_logic$empty),
        .almost_empty(read_logic$almost_empty),
        .underflow(read_logic$underflow),
        .write_address_delayed(read_logic$write_address_delayed),
        .ram_read_address(read_logic$ram_read_address),
        .ram_read_data(read_logic$ram_read_data),
        .ram_read_clock(read_logic$ram_read_clock),
        .read_address_out(read_logic$read_address_out),
        .fill_level(read_logic$fill_level)
    );
    skylux_core$raybox$result_fifo$write_logic write_logic(
        .write(write_logic$write),
        .data_in(write_logic$data_in),
        .full(write_logic$full),
        .almost_full(write_logic$almost_full),
        .overflow(write_logic$overflow),
        .clock(write_logic$clock),
        .ram_write_address(write_logic$ram_write_address),
        .ram_write_clock(write_logic$ram_write_clock),
        .ram_write_data(write_logic$ram_write_data),
        .ram_write_enable(write_logic$ram_write_enable),
        .read_address(write_logic$read_address),
        .write_address_delayed(write_logic$write_address_delayed),
        .fill_level(write_logic$fill_level)
    );
    
    // Update code
    always @(*) begin
        read_logic$clock = clock;
        write_logic$clock = clock;
        read_logic$read = read;
        empty = read_logic$empty;
        almost_empty = read_logic$almost_empty;
        data_out = read_logic$data_out;
        underflow = read_logic$underflow;
        overflow = write_logic$overflow;
        almost_full = write_logic$almost_full;
        full = write_logic$full;
        write_logic$write = write;
        write_logic$data_in = data_in;
        ram$write_clock = clock;
        ram$write_enable = write_logic$ram_write_enable;
        ram$write_address = write_logic$ram_write_address;
        ram$write_data = write_logic$ram_write_data;
        ram$read_clock = clock;
        ram$read_address = read_logic$ram_read_address;
        read_logic$ram_read_data = ram$read_data;
        read_logic$write_address_delayed = write_logic$write_address_delayed;
        write_logic$read_address = read_logic$read_address_out;
    end
    
endmodule // skylux_core$raybox$result_fifo


module skylux_core$raybox$result_fifo$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [3:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [3:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[63:0] mem[15:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // skylux_core$raybox$result_fifo$ram


module skylux_core$raybox$result_fifo$read_logic(clock,read,data_out,empty,almost_empty,underflow,write_address_delayed,ram_read_address,ram_read_data,ram_read_clock,read_address_out,fill_level);
    
    // Module arguments
    input wire  clock;
    input wire  read;
    output reg  [63:0] data_out;
    output reg  empty;
    output reg  almost_empty;
    output reg  underflow;
    input wire  [4:0] write_address_delayed;
    output reg  [3:0] ram_read_address;
    input wire  [63:0] ram_read_data;
    output reg  ram_read_clock;
    output reg  [4:0] read_address_out;
    output reg  [4:0] fill_level;
    
    // Constant declarations
    localparam  fifo_address_mask = 5'b1111;
    localparam  fifo_size = 5'b10000;
    localparam  block_size = 5'b1;
    
    // Stub signals
    reg  [4:0] read_address$d;
    wire  [4:0] read_address$q;
    reg  read_address$clock;
    reg  dff_underflow$d;
    wire  dff_underflow$q;
    reg  dff_underflow$clock;
    
    // Local signals
    reg  is_empty;
    reg  is_full;
    
    // Sub module instances
    skylux_core$raybox$result_fifo$read_logic$read_address read_address(
        .d(read_address$d),
        .q(read_address$q),
        .clock(read_address$clock)
    );
    skylux_core$raybox$result_fifo$read_logic$dff_underflow dff_underflow(
        .d(dff_underflow$d),
        .q(dff_underflow$q),
        .clock(dff_underflow$clock)
    );
    
    // Update code
    always @(*) begin
        read_address$clock = clock;
        dff_underflow$clock = clock;
        read_address$d = read_address$q;
        dff_underflow$d = dff_underflow$q;
        ram_read_clock = clock;
        is_empty = (read_address$q == write_address_delayed);
        is_full = ~is_empty & ((read_address$q & fifo_address_mask) == (write_address_delayed & fifo_address_mask));
        fill_level = ((write_address_delayed & fifo_address_mask) + fifo_size - (read_address$q & fifo_address_mask)) & fifo_address_mask;
        if (is_full) begin
            fill_level = fifo_size;
        end
        almost_empty = (fill_level < block_size);
        empty = is_empty;
        ram_read_address = ((read_address$q & fifo_address_mask) & 4'hf);
        data_out = ram_read_data;
        if (read & ~is_empty) begin
            read_address$d = read_address$q + 32'h1;
            ram_read_address = (((read_address$q + 32'h1) & fifo_address_mask) & 4'hf);
        end
        else begin
            read_address$d = read_address$q;
        end
        dff_underflow$d = dff_underflow$q | (is_empty & read);
        underflow = dff_underflow$q;
        read_address_out = read_address$q;
    end
    
endmodule // skylux_core$raybox$result_fifo$read_logic


module skylux_core$raybox$result_fifo$read_logic$dff_underflow(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$result_fifo$read_logic$dff_underflow


module skylux_core$raybox$result_fifo$read_logic$read_address(d,q,clock);
    
    // Module arguments
    input wire  [4:0] d;
    output reg  [4:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 5'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$result_fifo$read_logic$read_address


module skylux_core$raybox$result_fifo$write_logic(write,data_in,full,almost_full,overflow,clock,ram_write_address,ram_write_clock,ram_write_data,ram_write_enable,read_address,write_address_delayed,fill_level);
    
    // Module arguments
    input wire  write;
    input wire  [63:0] data_in;
    output reg  full;
    output reg  almost_full;
    output reg  overflow;
    input wire  clock;
    output reg  [3:0] ram_write_address;
    output reg  ram_write_clock;
    output reg  [63:0] ram_write_data;
    output reg  ram_write_enable;
    input wire  [4:0] read_address;
    output reg  [4:0] write_address_delayed;
    output reg  [4:0] fill_level;
    
    // Constant declarations
    localparam  fifo_address_mask = 5'b1111;
    localparam  fifo_size = 5'b10000;
    localparam  almost_full_level = 5'b1111;
    
    // Stub signals
    reg  [4:0] write_address$d;
    wire  [4:0] write_address$q;
    reg  write_address$clock;
    reg  [4:0] dff_write_address_delay$d;
    wire  [4:0] dff_write_address_delay$q;
    reg  dff_write_address_delay$clock;
    reg  dff_overflow$d;
    wire  dff_overflow$q;
    reg  dff_overflow$clock;
    
    // Local signals
    reg  is_empty;
    reg  is_full;
    
    // Sub module instances
    skylux_core$raybox$result_fifo$write_logic$write_address write_address(
        .d(write_address$d),
        .q(write_address$q),
        .clock(write_address$clock)
    );
    skylux_core$raybox$result_fifo$write_logic$dff_write_address_delay dff_write_address_delay(
        .d(dff_write_address_delay$d),
        .q(dff_write_address_delay$q),
        .clock(dff_write_address_delay$clock)
    );
    skylux_core$raybox$result_fifo$write_logic$dff_overflow dff_overflow(
        .d(dff_overflow$d),
        .q(dff_overflow$q),
        .clock(dff_overflow$clock)
    );
    
    // Update code
    always @(*) begin
        dff_overflow$clock = clock;
        write_address$clock = clock;
        dff_write_address_delay$clock = clock;
        dff_overflow$d = dff_overflow$q;
        write_address$d = write_address$q;
        dff_write_address_delay$d = dff_write_address_delay$q;
        ram_write_clock = clock;
        dff_write_address_delay$d = write_address$q;
        write_address_delayed = dff_write_address_delay$q;
        ram_write_enable = 1'b0;
        is_empty = (read_address == dff_write_address_delay$q);
        is_full = ~is_empty & ((read_address & fifo_address_mask) == (write_address$q & fifo_address_mask));
        fill_level = ((dff_write_address_delay$q & fifo_address_mask) + fifo_size - (read_address & fifo_address_mask)) & fifo_address_mask;
        if (is_full) begin
            fill_level = fifo_size;
        end
        almost_full = (fill_level >= almost_full_level);
        full = is_full;
        ram_write_address = ((write_address$q & fifo_address_mask) & 4'hf);
        ram_write_data = data_in;
        if (write & ~is_full) begin
            write_address$d = write_address$q + 32'h1;
            ram_write_enable = 1'b1;
        end
        else begin
            write_address$d = write_address$q;
            ram_write_enable = 1'b0;
        end
        dff_overflow$d = dff_overflow$q | (is_full & write);
        overflow = dff_overflow$q;
    end
    
endmodule // skylux_core$raybox$result_fifo$write_logic


module skylux_core$raybox$result_fifo$write_logic$dff_overflow(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$result_fifo$write_logic$dff_overflow


module skylux_core$raybox$result_fifo$write_logic$dff_write_address_delay(d,q,clock);
    
    // Module arguments
    input wire  [4:0] d;
    output reg  [4:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 5'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$result_fifo$write_logic$dff_write_address_delay


module skylux_core$raybox$result_fifo$write_logic$write_address(d,q,clock);
    
    // Module arguments
    input wire  [4:0] d;
    output reg  [4:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 5'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$result_fifo$write_logic$write_address


module skylux_core$raybox$shift_xy(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$shift_xy


module skylux_core$raybox$shift_z(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$shift_z


module skylux_core$raybox$stale(d,q,clock);
    
    // Module arguments
    input wire  [4:0] d;
    output reg  [4:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 5'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$stale


module skylux_core$raybox$state(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Enums
    localparam UnitState$Idle = 0;
    localparam UnitState$Check = 1;
    localparam UnitState$Run = 2;
    localparam UnitState$Finish = 3;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$state


module skylux_core$raybox$t_max(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$t_max


module skylux_core$raybox$t_min(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$t_min


module skylux_core$raybox$timeout_pulse(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$timeout_pulse


module skylux_core$raybox$watchdog(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$watchdog


module skylux_core$raybox$window_pulse(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$window_pulse


module skylux_core$raybox$word_index(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$word_index


module skylux_core$raybox$work_addr(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$work_addr


module skylux_core$raybox$written(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$raybox$written


module skylux_core$regs(clock,avs_address,avs_read,avs_write,avs_writedata,avs_byteenable,avs_readdata,irq,sys_scratch_value,sys_bus_status_unmapped_read,sys_bus_status_unmapped_write,sys_time_lo_cycles,sys_time_hi_cycles,sys_irq_status_frame_done,sys_irq_status_frame_done_set,sys_irq_status_sequence_done,sys_irq_status_sequence_done_set,sys_irq_status_dma_error,sys_irq_status_dma_error_set,sys_irq_status_capture_error,sys_irq_status_capture_error_set,sys_irq_status_i2c_done,sys_irq_status_i2c_done_set,sys_irq_status_raybox_done,sys_irq_status_raybox_done_set,sys_irq_enable_frame_done,sys_irq_enable_sequence_done,sys_irq_enable_dma_error,sys_irq_enable_capture_error,sys_irq_enable_i2c_done,sys_irq_enable_raybox_done,i2c_ctrl_start,i2c_ctrl_read,i2c_target_addr7,i2c_reg_addr_addr,i2c_write_data_data,i2c_read_data_data,i2c_status_busy,i2c_status_done,i2c_status_done_set,i2c_status_nack,i2c_status_nack_set,i2c_status_timeout,i2c_status_timeout_set,i2c_status_bus_stuck,i2c_status_bus_stuck_set,i2c_status_refused,i2c_status_refused_set,i2c_clock_div_half_period,i2c_timeout_cycles,i2c_sensor_pins_reset_n,i2c_sensor_pins_strobe,seq_ctrl_start,seq_ctrl_abort,seq_ctrl_ext_trigger,seq_count_exposures,seq_status_busy,seq_status_index,seq_status_shield_open,seq_status_done,seq_status_done_set,seq_status_shield_limit_hit,seq_status_shield_limit_hit_set,seq_status_i2c_error,seq_status_i2c_error_set,seq_status_refused,seq_status_refused_set,seq_status_aborted,seq_status_aborted_set,seq_shield_limit_cycles,seq_shield_steps_steps,seq_shield_step_period_cycles,seq_frame_number_value,seq_trigger_pulse_cycles,seq_exp_shutter_width_rows$0,seq_exp_shutter_width_rows$1,seq_exp_shutter_width_rows$2,seq_exp_shutter_width_rows$3,seq_exp_shutter_width_rows$4,seq_exp_shutter_width_rows$5,seq_exp_shutter_width_rows$6,seq_exp_shutter_width_rows$7,seq_exp_shutter_delay_value$0,seq_exp_shutter_delay_value$1,seq_exp_shutter_delay_value$2,seq_exp_shutter_delay_value$3,seq_exp_shutter_delay_value$4,seq_exp_shutter_delay_value$5,seq_exp_shutter_delay_value$6,seq_exp_shutter_delay_value$7,seq_exp_gain_code$0,seq_exp_gain_code$1,seq_exp_gain_code$2,seq_exp_gain_code$3,seq_exp_gain_code$4,seq_exp_gain_code$5,seq_exp_gain_code$6,seq_exp_gain_code$7,capture_ctrl_enable,capture_ctrl_raw,capture_window_width,capture_window_height,capture_status_frame_valid,capture_status_line_short,capture_status_line_short_set,capture_status_line_long,capture_status_line_long_set,capture_status_frame_short,capture_status_frame_short_set,capture_status_frame_long,capture_status_frame_long_set,capture_status_fifo_overflow,capture_status_fifo_overflow_set,capture_status_pixclk_stopped,capture_status_pixclk_stopped_set,capture_last_frame_pixels,capture_last_frame_lines,capture_fifo_high_water_words,capture_frames_count,bayer_mode_phase,bayer_black_level,bayer_valid_min,bayer_valid_max,bayer_weight_r_q2_14,bayer_weight_g_q2_14,bayer_weight_b_q2_14,dma_ctrl_enable,dma_ctrl_reset,dma_window_base_addr,dma_window_size_bytes,dma_slot_stride_bytes,dma_slots_count,dma_status_busy,dma_status_slot,dma_status_frame_done,dma_status_frame_done_set,dma_status_out_of_window,dma_status_out_of_window_set,dma_status_overflow,dma_status_overflow_set,dma_status_bus_timeout,dma_status_bus_timeout_set,dma_frames_written_count,dma_bus_timeout_cycles,raybox_ctrl_start,raybox_ctrl_abort,raybox_work_base_addr,raybox_work_count_items,raybox_result_base_addr,raybox_window_base_addr,raybox_window_size_bytes,raybox_status_busy,raybox_status_done,raybox_status_done_set,raybox_status_bad_descriptor,raybox_status_bad_descriptor_set,raybox_status_out_of_window,raybox_status_out_of_window_set,raybox_status_bus_timeout,raybox_status_bus_timeout_set,raybox_tests_done_count,raybox_info_lanes,raybox_bus_timeout_cycles,sun_ctrl_enable,sun_ctrl_exposure_index,sun_threshold_q14,sun_window_x_min,sun_window_x_max,sun_window_y_min,sun_window_y_max,sun_count_groups,sun_over_count_groups,sun_sum_l_lo_value,sun_sum_l_hi_value,sun_sum_xl_lo_value,sun_sum_xl_hi_value,sun_sum_yl_lo_value,sun_sum_yl_hi_value,sun_max_l_q14,sun_box_x_min,sun_box_x_max,sun_box_y_min,sun_box_y_max,sun_frames_count,hdr_ctrl_enable,hdr_ctrl_new_set,hdr_min_q11,hdr_max_q11);
    
    // Module arguments
    input wire  clock;
    input wire  [18:0] avs_address;
    input wire  avs_read;
    input wire  avs_write;
    input wire  [31:0] avs_writedata;
    input wire  [3:0] avs_byteenable;
    output reg  [31:0] avs_readdata;
    output reg  irq;
    output reg  [31:0] sys_scratch_value;
    output reg  sys_bus_status_unmapped_read;
    output reg  sys_bus_status_unmapped_write;
    input wire  [31:0] sys_time_lo_cycles;
    input wire  [31:0] sys_time_hi_cycles;
    output reg  sys_irq_status_frame_done;
    input wire  sys_irq_status_frame_done_set;
    output reg  sys_irq_status_sequence_done;
    input wire  sys_irq_status_sequence_done_set;
    output reg  sys_irq_status_dma_error;
    input wire  sys_irq_status_dma_error_set;
    output reg  sys_irq_status_capture_error;
    input wire  sys_irq_status_capture_error_set;
    output reg  sys_irq_status_i2c_done;
    input wire  sys_irq_status_i2c_done_set;
    output reg  sys_irq_status_raybox_done;
    input wire  sys_irq_status_raybox_done_set;
    output reg  sys_irq_enable_frame_done;
    output reg  sys_irq_enable_sequence_done;
    output reg  sys_irq_enable_dma_error;
    output reg  sys_irq_enable_capture_error;
    output reg  sys_irq_enable_i2c_done;
    output reg  sys_irq_enable_raybox_done;
    output reg  i2c_ctrl_start;
    output reg  i2c_ctrl_read;
    output reg  [6:0] i2c_target_addr7;
    output reg  [7:0] i2c_reg_addr_addr;
    output reg  [15:0] i2c_write_data_data;
    input wire  [15:0] i2c_read_data_data;
    input wire  i2c_status_busy;
    output reg  i2c_status_done;
    input wire  i2c_status_done_set;
    output reg  i2c_status_nack;
    input wire  i2c_status_nack_set;
    output reg  i2c_status_timeout;
    input wire  i2c_status_timeout_set;
    output reg  i2c_status_bus_stuck;
    input wire  i2c_status_bus_stuck_set;
    output reg  i2c_status_refused;
    input wire  i2c_status_refused_set;
    output reg  [15:0] i2c_clock_div_half_period;
    output reg  [23:0] i2c_timeout_cycles;
    output reg  i2c_sensor_pins_reset_n;
    input wire  i2c_sensor_pins_strobe;
    output reg  seq_ctrl_start;
    output reg  seq_ctrl_abort;
    output reg  seq_ctrl_ext_trigger;
    output reg  [3:0] seq_count_exposures;
    input wire  seq_status_busy;
    input wire  [2:0] seq_status_index;
    input wire  seq_status_shield_open;
    output reg  seq_status_done;
    input wire  seq_status_done_set;
    output reg  seq_status_shield_limit_hit;
    input wire  seq_status_shield_limit_hit_set;
    output reg  seq_status_i2c_error;
    input wire  seq_status_i2c_error_set;
    output reg  seq_status_refused;
    input wire  seq_status_refused_set;
    output reg  seq_status_aborted;
    input wire  seq_status_aborted_set;
    output reg  [31:0] seq_shield_limit_cycles;
    output reg  [15:0] seq_shield_steps_steps;
    output reg  [23:0] seq_shield_step_period_cycles;
    input wire  [31:0] seq_frame_number_value;
    output reg  [15:0] seq_trigger_pulse_cycles;
    output reg  [19:0] seq_exp_shutter_width_rows$0;
    output reg  [19:0] seq_exp_shutter_width_rows$1;
    output reg  [19:0] seq_exp_shutter_width_rows$2;
    output reg  [19:0] seq_exp_shutter_width_rows$3;
    output reg  [19:0] seq_exp_shutter_width_rows$4;
    output reg  [19:0] seq_exp_shutter_width_rows$5;
    output reg  [19:0] seq_exp_shutter_width_rows$6;
    output reg  [19:0] seq_exp_shutter_width_rows$7;
    output reg  [12:0] seq_exp_shutter_delay_value$0;
    output reg  [12:0] seq_exp_shutter_delay_value$1;
    output reg  [12:0] seq_exp_shutter_delay_value$2;
    output reg  [12:0] seq_exp_shutter_delay_value$3;
    output reg  [12:0] seq_exp_shutter_delay_value$4;
    output reg  [12:0] seq_exp_shutter_delay_value$5;
    output reg  [12:0] seq_exp_shutter_delay_value$6;
    output reg  [12:0] seq_exp_shutter_delay_value$7;
    output reg  [15:0] seq_exp_gain_code$0;
    output reg  [15:0] seq_exp_gain_code$1;
    output reg  [15:0] seq_exp_gain_code$2;
    output reg  [15:0] seq_exp_gain_code$3;
    output reg  [15:0] seq_exp_gain_code$4;
    output reg  [15:0] seq_exp_gain_code$5;
    output reg  [15:0] seq_exp_gain_code$6;
    output reg  [15:0] seq_exp_gain_code$7;
    output reg  capture_ctrl_enable;
    output reg  capture_ctrl_raw;
    output reg  [11:0] capture_window_width;
    output reg  [11:0] capture_window_height;
    input wire  capture_status_frame_valid;
    output reg  capture_status_line_short;
    input wire  capture_status_line_short_set;
    output reg  capture_status_line_long;
    input wire  capture_status_line_long_set;
    output reg  capture_status_frame_short;
    input wire  capture_status_frame_short_set;
    output reg  capture_status_frame_long;
    input wire  capture_status_frame_long_set;
    output reg  capture_status_fifo_overflow;
    input wire  capture_status_fifo_overflow_set;
    output reg  capture_status_pixclk_stopped;
    input wire  capture_status_pixclk_stopped_set;
    input wire  [11:0] capture_last_frame_pixels;
    input wire  [11:0] capture_last_frame_lines;
    input wire  [15:0] capture_fifo_high_water_words;
    input wire  [31:0] capture_frames_count;
    output reg  [1:0] bayer_mode_phase;
    output reg  [11:0] bayer_black_level;
    output reg  [11:0] bayer_valid_min;
    output reg  [11:0] bayer_valid_max;
    output reg  [15:0] bayer_weight_r_q2_14;
    output reg  [15:0] bayer_weight_g_q2_14;
    output reg  [15:0] bayer_weight_b_q2_14;
    output reg  dma_ctrl_enable;
    output reg  dma_ctrl_reset;
    output reg  [31:0] dma_window_base_addr;
    output reg  [31:0] dma_window_size_bytes;
    output reg  [31:0] dma_slot_stride_bytes;
    output reg  [7:0] dma_slots_count;
    input wire  dma_status_busy;
    input wire  [7:0] dma_status_slot;
    output reg  dma_status_frame_done;
    input wire  dma_status_frame_done_set;
    output reg  dma_status_out_of_window;
    input wire  dma_status_out_of_window_set;
    output reg  dma_status_overflow;
    input wire  dma_status_overflow_set;
    output reg  dma_status_bus_timeout;
    input wire  dma_status_bus_timeout_set;
    input wire  [31:0] dma_frames_written_count;
    output reg  [23:0] dma_bus_timeout_cycles;
    output reg  raybox_ctrl_start;
    output reg  raybox_ctrl_abort;
    output reg  [31:0] raybox_work_base_addr;
    output reg  [23:0] raybox_work_count_items;
    output reg  [31:0] raybox_result_base_addr;
    output reg  [31:0] raybox_window_base_addr;
    output reg  [31:0] raybox_window_size_bytes;
    input wire  raybox_status_busy;
    output reg  raybox_status_done;
    input wire  raybox_status_done_set;
    output reg  raybox_status_bad_descriptor;
    input wire  raybox_status_bad_descriptor_set;
    output reg  raybox_status_out_of_window;
    input wire  raybox_status_out_of_window_set;
    output reg  raybox_status_bus_timeout;
    input wire  raybox_status_bus_timeout_set;
    input wire  [31:0] raybox_tests_done_count;
    input wire  [7:0] raybox_info_lanes;
    output reg  [23:0] raybox_bus_timeout_cycles;
    output reg  sun_ctrl_enable;
    output reg  [2:0] sun_ctrl_exposure_index;
    output reg  [29:0] sun_threshold_q14;
    output reg  [10:0] sun_window_x_min;
    output reg  [10:0] sun_window_x_max;
    output reg  [10:0] sun_window_y_min;
    output reg  [10:0] sun_window_y_max;
    input wire  [20:0] sun_count_groups;
    input wire  [20:0] sun_over_count_groups;
    input wire  [31:0] sun_sum_l_lo_value;
    input wire  [31:0] sun_sum_l_hi_value;
    input wire  [31:0] sun_sum_xl_lo_value;
    input wire  [31:0] sun_sum_xl_hi_value;
    input wire  [31:0] sun_sum_yl_lo_value;
    input wire  [31:0] sun_sum_yl_hi_value;
    input wire  [29:0] sun_max_l_q14;
    input wire  [10:0] sun_box_x_min;
    input wire  [10:0] sun_box_x_max;
    input wire  [10:0] sun_box_y_min;
    input wire  [10:0] sun_box_y_max;
    input wire  [15:0] sun_frames_count;
    output reg  hdr_ctrl_enable;
    output reg  hdr_ctrl_new_set;
    output reg  [26:0] hdr_min_q11;
    output reg  [26:0] hdr_max_q11;
    
    // Stub signals
    reg  [31:0] rdata$d;
    wire  [31:0] rdata$q;
    reg  rdata$clock;
    reg  [18:0] error_word$d;
    wire  [18:0] error_word$q;
    reg  error_word$clock;
    reg  [31:0] r_sys_scratch$d;
    wire  [31:0] r_sys_scratch$q;
    reg  r_sys_scratch$clock;
    reg  [31:0] r_sys_bus_status$d;
    wire  [31:0] r_sys_bus_status$q;
    reg  r_sys_bus_status$clock;
    reg  [31:0] r_sys_irq_status$d;
    wire  [31:0] r_sys_irq_status$q;
    reg  r_sys_irq_status$clock;
    reg  [31:0] r_sys_irq_enable$d;
    wire  [31:0] r_sys_irq_enable$q;
    reg  r_sys_irq_enable$clock;
    reg  [31:0] r_i2c_ctrl$d;
    wire  [31:0] r_i2c_ctrl$q;
    reg  r_i2c_ctrl$clock;
    reg  [31:0] p_i2c_ctrl$d;
    wire  [31:0] p_i2c_ctrl$q;
    reg  p_i2c_ctrl$clock;
    reg  [31:0] r_i2c_target$d;
    wire  [31:0] r_i2c_target$q;
    reg  r_i2c_target$clock;
    reg  [31:0] r_i2c_reg_addr$d;
    wire  [31:0] r_i2c_reg_addr$q;
    reg  r_i2c_reg_addr$clock;
    reg  [31:0] r_i2c_write_data$d;
    wire  [31:0] r_i2c_write_data$q;
    reg  r_i2c_write_data$clock;
    reg  [31:0] r_i2c_status$d;
    wire  [31:0] r_i2c_status$q;
    reg  r_i2c_status$clock;
    reg  [31:0] r_i2c_clock_div$d;
    wire  [31:0] r_i2c_clock_div$q;
    reg  r_i2c_clock_div$clock;
    reg  [31:0] r_i2c_timeout$d;
    wire  [31:0] r_i2c_timeout$q;
    reg  r_i2c_timeout$clock;
    reg  [31:0] r_i2c_sensor_pins$d;
    wire  [31:0] r_i2c_sensor_pins$q;
    reg  r_i2c_sensor_pins$clock;
    reg  [31:0] r_seq_ctrl$d;
    wire  [31:0] r_seq_ctrl$q;
    reg  r_seq_ctrl$clock;
    reg  [31:0] p_seq_ctrl$d;
    wire  [31:0] p_seq_ctrl$q;
    reg  p_seq_ctrl$clock;
    reg  [31:0] r_seq_count$d;
    wire  [31:0] r_seq_count$q;
    reg  r_seq_count$clock;
    reg  [31:0] r_seq_status$d;
    wire  [31:0] r_seq_status$q;
    reg  r_seq_status$clock;
    reg  [31:0] r_seq_shield_limit$d;
    wire  [31:0] r_seq_shield_limit$q;
    reg  r_seq_shield_limit$clock;
    reg  [31:0] r_seq_shield_steps$d;
    wire  [31:0] r_seq_shield_steps$q;
    reg  r_seq_shield_steps$clock;
    reg  [31:0] r_seq_shield_step_period$d;
    wire  [31:0] r_seq_shield_step_period$q;
    reg  r_seq_shield_step_period$clock;
    reg  [31:0] r_seq_trigger_pulse$d;
    wire  [31:0] r_seq_trigger_pulse$q;
    reg  r_seq_trigger_pulse$clock;
    reg  [31:0] r_seq_exp_shutter_width_0$d;
    wire  [31:0] r_seq_exp_shutter_width_0$q;
    reg  r_seq_exp_shutter_width_0$clock;
    reg  [31:0] r_seq_exp_shutter_width_1$d;
    wire  [31:0] r_seq_exp_shutter_width_1$q;
    reg  r_seq_exp_shutter_width_1$clock;
    reg  [31:0] r_seq_exp_shutter_width_2$d;
    wire  [31:0] r_seq_exp_shutter_width_2$q;
    reg  r_seq_exp_shutter_width_2$clock;
    reg  [31:0] r_seq_exp_shutter_width_3$d;
    wire  [31:0] r_seq_exp_shutter_width_3$q;
    reg  r_seq_exp_shutter_width_3$clock;
    reg  [31:0] r_seq_exp_shutter_width_4$d;
    wire  [31:0] r_seq_exp_shutter_width_4$q;
    reg  r_seq_exp_shutter_width_4$clock;
    reg  [31:0] r_seq_exp_shutter_width_5$d;
    wire  [31:0] r_seq_exp_shutter_width_5$q;
    reg  r_seq_exp_shutter_width_5$clock;
    reg  [31:0] r_seq_exp_shutter_width_6$d;
    wire  [31:0] r_seq_exp_shutter_width_6$q;
    reg  r_seq_exp_shutter_width_6$clock;
    reg  [31:0] r_seq_exp_shutter_width_7$d;
    wire  [31:0] r_seq_exp_shutter_width_7$q;
    reg  r_seq_exp_shutter_width_7$clock;
    reg  [31:0] r_seq_exp_shutter_delay_0$d;
    wire  [31:0] r_seq_exp_shutter_delay_0$q;
    reg  r_seq_exp_shutter_delay_0$clock;
    reg  [31:0] r_seq_exp_shutter_delay_1$d;
    wire  [31:0] r_seq_exp_shutter_delay_1$q;
    reg  r_seq_exp_shutter_delay_1$clock;
    reg  [31:0] r_seq_exp_shutter_delay_2$d;
    wire  [31:0] r_seq_exp_shutter_delay_2$q;
    reg  r_seq_exp_shutter_delay_2$clock;
    reg  [31:0] r_seq_exp_shutter_delay_3$d;
    wire  [31:0] r_seq_exp_shutter_delay_3$q;
    reg  r_seq_exp_shutter_delay_3$clock;
    reg  [31:0] r_seq_exp_shutter_delay_4$d;
    wire  [31:0] r_seq_exp_shutter_delay_4$q;
    reg  r_seq_exp_shutter_delay_4$clock;
    reg  [31:0] r_seq_exp_shutter_delay_5$d;
    wire  [31:0] r_seq_exp_shutter_delay_5$q;
    reg  r_seq_exp_shutter_delay_5$clock;
    reg  [31:0] r_seq_exp_shutter_delay_6$d;
    wire  [31:0] r_seq_exp_shutter_delay_6$q;
    reg  r_seq_exp_shutter_delay_6$clock;
    reg  [31:0] r_seq_exp_shutter_delay_7$d;
    wire  [31:0] r_seq_exp_shutter_delay_7$q;
    reg  r_seq_exp_shutter_delay_7$clock;
    reg  [31:0] r_seq_exp_gain_0$d;
    wire  [31:0] r_seq_exp_gain_0$q;
    reg  r_seq_exp_gain_0$clock;
    reg  [31:0] r_seq_exp_gain_1$d;
    wire  [31:0] r_seq_exp_gain_1$q;
    reg  r_seq_exp_gain_1$clock;
    reg  [31:0] r_seq_exp_gain_2$d;
    wire  [31:0] r_seq_exp_gain_2$q;
    reg  r_seq_exp_gain_2$clock;
    reg  [31:0] r_seq_exp_gain_3$d;
    wire  [31:0] r_seq_exp_gain_3$q;
    reg  r_seq_exp_gain_3$clock;
    reg  [31:0] r_seq_exp_gain_4$d;
    wire  [31:0] r_seq_exp_gain_4$q;
    reg  r_seq_exp_gain_4$clock;
    reg  [31:0] r_seq_exp_gain_5$d;
    wire  [31:0] r_seq_exp_gain_5$q;
    reg  r_seq_exp_gain_5$clock;
    reg  [31:0] r_seq_exp_gain_6$d;
    wire  [31:0] r_seq_exp_gain_6$q;
    reg  r_seq_exp_gain_6$clock;
    reg  [31:0] r_seq_exp_gain_7$d;
    wire  [31:0] r_seq_exp_gain_7$q;
    reg  r_seq_exp_gain_7$clock;
    reg  [31:0] r_capture_ctrl$d;
    wire  [31:0] r_capture_ctrl$q;
    reg  r_capture_ctrl$clock;
    reg  [31:0] r_capture_window$d;
    wire  [31:0] r_capture_window$q;
    reg  r_capture_window$clock;
    reg  [31:0] r_capture_status$d;
    wire  [31:0] r_capture_status$q;
    reg  r_capture_status$clock;
    reg  [31:0] r_bayer_mode$d;
    wire  [31:0] r_bayer_mode$q;
    reg  r_bayer_mode$clock;
    reg  [31:0] r_bayer_black$d;
    wire  [31:0] r_bayer_black$q;
    reg  r_bayer_black$clock;
    reg  [31:0] r_bayer_valid$d;
    wire  [31:0] r_bayer_valid$q;
    reg  r_bayer_valid$clock;
    reg  [31:0] r_bayer_weight_r$d;
    wire  [31:0] r_bayer_weight_r$q;
    reg  r_bayer_weight_r$clock;
    reg  [31:0] r_bayer_weight_g$d;
    wire  [31:0] r_bayer_weight_g$q;
    reg  r_bayer_weight_g$clock;
    reg  [31:0] r_bayer_weight_b$d;
    wire  [31:0] r_bayer_weight_b$q;
    reg  r_bayer_weight_b$clock;
    reg  [31:0] r_dma_ctrl$d;
    wire  [31:0] r_dma_ctrl$q;
    reg  r_dma_ctrl$clock;
    reg  [31:0] p_dma_ctrl$d;
    wire  [31:0] p_dma_ctrl$q;
    reg  p_dma_ctrl$clock;
    reg  [31:0] r_dma_window_base$d;
    wire  [31:0] r_dma_window_base$q;
    reg  r_dma_window_base$clock;
    reg  [31:0] r_dma_window_size$d;
    wire  [31:0] r_dma_window_size$q;
    reg  r_dma_window_size$clock;
    reg  [31:0] r_dma_slot_stride$d;
    wire  [31:0] r_dma_slot_stride$q;
    reg  r_dma_slot_stride$clock;
    reg  [31:0] r_dma_slots$d;
    wire  [31:0] r_dma_slots$q;
    reg  r_dma_slots$clock;
    reg  [31:0] r_dma_status$d;
    wire  [31:0] r_dma_status$q;
    reg  r_dma_status$clock;
    reg  [31:0] r_dma_bus_timeout$d;
    wire  [31:0] r_dma_bus_timeout$q;
    reg  r_dma_bus_timeout$clock;
    reg  [31:0] p_raybox_ctrl$d;
    wire  [31:0] p_raybox_ctrl$q;
    reg  p_raybox_ctrl$clock;
    reg  [31:0] r_raybox_work_base$d;
    wire  [31:0] r_raybox_work_base$q;
    reg  r_raybox_work_base$clock;
    reg  [31:0] r_raybox_work_count$d;
    wire  [31:0] r_raybox_work_count$q;
    reg  r_raybox_work_count$clock;
    reg  [31:0] r_raybox_result_base$d;
    wire  [31:0] r_raybox_result_base$q;
    reg  r_raybox_result_base$clock;
    reg  [31:0] r_raybox_window_base$d;
    wire  [31:0] r_raybox_window_base$q;
    reg  r_raybox_window_base$clock;
    reg  [31:0] r_raybox_window_size$d;
    wire  [31:0] r_raybox_window_size$q;
    reg  r_raybox_window_size$clock;
    reg  [31:0] r_raybox_status$d;
    wire  [31:0] r_raybox_status$q;
    reg  r_raybox_status$clock;
    reg  [31:0] r_raybox_bus_timeout$d;
    wire  [31:0] r_raybox_bus_timeout$q;
    reg  r_raybox_bus_timeout$clock;
    reg  [31:0] r_sun_ctrl$d;
    wire  [31:0] r_sun_ctrl$q;
    reg  r_sun_ctrl$clock;
    reg  [31:0] r_sun_threshold$d;
    wire  [31:0] r_sun_threshold$q;
    reg  r_sun_threshold$clock;
    reg  [31:0] r_sun_window_x$d;
    wire  [31:0] r_sun_window_x$q;
    reg  r_sun_window_x$clock;
    reg  [31:0] r_sun_window_y$d;
    wire  [31:0] r_sun_window_y$q;
    reg  r_sun_window_y$clock;
    reg  [31:0] r_hdr_ctrl$d;
    wire  [31:0] r_hdr_ctrl$q;
    reg  r_hdr_ctrl$clock;
    reg  [31:0] p_hdr_ctrl$d;
    wire  [31:0] p_hdr_ctrl$q;
    reg  p_hdr_ctrl$clock;
    reg  [31:0] r_hdr_min$d;
    wire  [31:0] r_hdr_min$q;
    reg  r_hdr_min$clock;
    reg  [31:0] r_hdr_max$d;
    wire  [31:0] r_hdr_max$q;
    reg  r_hdr_max$clock;
    
    // Local signals
    reg  [31:0] byte_mask;
    reg  unmapped_read;
    reg  unmapped_write;
    reg  [31:0] nx_sys_scratch;
    reg  [31:0] nx_sys_bus_status;
    reg  [31:0] nx_sys_irq_status;
    reg  [31:0] nx_sys_irq_enable;
    reg  [31:0] nx_i2c_ctrl;
    reg  [31:0] nx_i2c_target;
    reg  [31:0] nx_i2c_reg_addr;
    reg  [31:0] nx_i2c_write_data;
    reg  [31:0] nx_i2c_status;
    reg  [31:0] nx_i2c_clock_div;
    reg  [31:0] nx_i2c_timeout;
    reg  [31:0] nx_i2c_sensor_pins;
    reg  [31:0] nx_seq_ctrl;
    reg  [31:0] nx_seq_count;
    reg  [31:0] nx_seq_status;
    reg  [31:0] nx_seq_shield_limit;
    reg  [31:0] nx_seq_shield_steps;
    reg  [31:0] nx_seq_shield_step_period;
    reg  [31:0] nx_seq_trigger_pulse;
    reg  [31:0] nx_seq_exp_shutter_width_0;
    reg  [31:0] nx_seq_exp_shutter_width_1;
    reg  [31:0] nx_seq_exp_shutter_width_2;
    reg  [31:0] nx_seq_exp_shutter_width_3;
    reg  [31:0] nx_seq_exp_shutter_width_4;
    reg  [31:0] nx_seq_exp_shutter_width_5;
    reg  [31:0] nx_seq_exp_shutter_width_6;
    reg  [31:0] nx_seq_exp_shutter_width_7;
    reg  [31:0] nx_seq_exp_shutter_delay_0;
    reg  [31:0] nx_seq_exp_shutter_delay_1;
    reg  [31:0] nx_seq_exp_shutter_delay_2;
    reg  [31:0] nx_seq_exp_shutter_delay_3;
    reg  [31:0] nx_seq_exp_shutter_delay_4;
    reg  [31:0] nx_seq_exp_shutter_delay_5;
    reg  [31:0] nx_seq_exp_shutter_delay_6;
    reg  [31:0] nx_seq_exp_shutter_delay_7;
    reg  [31:0] nx_seq_exp_gain_0;
    reg  [31:0] nx_seq_exp_gain_1;
    reg  [31:0] nx_seq_exp_gain_2;
    reg  [31:0] nx_seq_exp_gain_3;
    reg  [31:0] nx_seq_exp_gain_4;
    reg  [31:0] nx_seq_exp_gain_5;
    reg  [31:0] nx_seq_exp_gain_6;
    reg  [31:0] nx_seq_exp_gain_7;
    reg  [31:0] nx_capture_ctrl;
    reg  [31:0] nx_capture_window;
    reg  [31:0] nx_capture_status;
    reg  [31:0] nx_bayer_mode;
    reg  [31:0] nx_bayer_black;
    reg  [31:0] nx_bayer_valid;
    reg  [31:0] nx_bayer_weight_r;
    reg  [31:0] nx_bayer_weight_g;
    reg  [31:0] nx_bayer_weight_b;
    reg  [31:0] nx_dma_ctrl;
    reg  [31:0] nx_dma_window_base;
    reg  [31:0] nx_dma_window_size;
    reg  [31:0] nx_dma_slot_stride;
    reg  [31:0] nx_dma_slots;
    reg  [31:0] nx_dma_status;
    reg  [31:0] nx_dma_bus_timeout;
    reg  [31:0] nx_raybox_work_base;
    reg  [31:0] nx_raybox_work_count;
    reg  [31:0] nx_raybox_result_base;
    reg  [31:0] nx_raybox_window_base;
    reg  [31:0] nx_raybox_window_size;
    reg  [31:0] nx_raybox_status;
    reg  [31:0] nx_raybox_bus_timeout;
    reg  [31:0] nx_sun_ctrl;
    reg  [31:0] nx_sun_threshold;
    reg  [31:0] nx_sun_window_x;
    reg  [31:0] nx_sun_window_y;
    reg  [31:0] nx_hdr_ctrl;
    reg  [31:0] nx_hdr_min;
    reg  [31:0] nx_hdr_max;
    
    // Sub module instances
    skylux_core$regs$rdata rdata(
        .d(rdata$d),
        .q(rdata$q),
        .clock(rdata$clock)
    );
    skylux_core$regs$error_word error_word(
        .d(error_word$d),
        .q(error_word$q),
        .clock(error_word$clock)
    );
    skylux_core$regs$r_sys_scratch r_sys_scratch(
        .d(r_sys_scratch$d),
        .q(r_sys_scratch$q),
        .clock(r_sys_scratch$clock)
    );
    skylux_core$regs$r_sys_bus_status r_sys_bus_status(
        .d(r_sys_bus_status$d),
        .q(r_sys_bus_status$q),
        .clock(r_sys_bus_status$clock)
    );
    skylux_core$regs$r_sys_irq_status r_sys_irq_status(
        .d(r_sys_irq_status$d),
        .q(r_sys_irq_status$q),
        .clock(r_sys_irq_status$clock)
    );
    skylux_core$regs$r_sys_irq_enable r_sys_irq_enable(
        .d(r_sys_irq_enable$d),
        .q(r_sys_irq_enable$q),
        .clock(r_sys_irq_enable$clock)
    );
    skylux_core$regs$r_i2c_ctrl r_i2c_ctrl(
        .d(r_i2c_ctrl$d),
        .q(r_i2c_ctrl$q),
        .clock(r_i2c_ctrl$clock)
    );
    skylux_core$regs$p_i2c_ctrl p_i2c_ctrl(
        .d(p_i2c_ctrl$d),
        .q(p_i2c_ctrl$q),
        .clock(p_i2c_ctrl$clock)
    );
    skylux_core$regs$r_i2c_target r_i2c_target(
        .d(r_i2c_target$d),
        .q(r_i2c_target$q),
        .clock(r_i2c_target$clock)
    );
    skylux_core$regs$r_i2c_reg_addr r_i2c_reg_addr(
        .d(r_i2c_reg_addr$d),
        .q(r_i2c_reg_addr$q),
        .clock(r_i2c_reg_addr$clock)
    );
    skylux_core$regs$r_i2c_write_data r_i2c_write_data(
        .d(r_i2c_write_data$d),
        .q(r_i2c_write_data$q),
        .clock(r_i2c_write_data$clock)
    );
    skylux_core$regs$r_i2c_status r_i2c_status(
        .d(r_i2c_status$d),
        .q(r_i2c_status$q),
        .clock(r_i2c_status$clock)
    );
    skylux_core$regs$r_i2c_clock_div r_i2c_clock_div(
        .d(r_i2c_clock_div$d),
        .q(r_i2c_clock_div$q),
        .clock(r_i2c_clock_div$clock)
    );
    skylux_core$regs$r_i2c_timeout r_i2c_timeout(
        .d(r_i2c_timeout$d),
        .q(r_i2c_timeout$q),
        .clock(r_i2c_timeout$clock)
    );
    skylux_core$regs$r_i2c_sensor_pins r_i2c_sensor_pins(
        .d(r_i2c_sensor_pins$d),
        .q(r_i2c_sensor_pins$q),
        .clock(r_i2c_sensor_pins$clock)
    );
    skylux_core$regs$r_seq_ctrl r_seq_ctrl(
        .d(r_seq_ctrl$d),
        .q(r_seq_ctrl$q),
        .clock(r_seq_ctrl$clock)
    );
    skylux_core$regs$p_seq_ctrl p_seq_ctrl(
        .d(p_seq_ctrl$d),
        .q(p_seq_ctrl$q),
        .clock(p_seq_ctrl$clock)
    );
    skylux_core$regs$r_seq_count r_seq_count(
        .d(r_seq_count$d),
        .q(r_seq_count$q),
        .clock(r_seq_count$clock)
    );
    skylux_core$regs$r_seq_status r_seq_status(
        .d(r_seq_status$d),
        .q(r_seq_status$q),
        .clock(r_seq_status$clock)
    );
    skylux_core$regs$r_seq_shield_limit r_seq_shield_limit(
        .d(r_seq_shield_limit$d),
        .q(r_seq_shield_limit$q),
        .clock(r_seq_shield_limit$clock)
    );
    skylux_core$regs$r_seq_shield_steps r_seq_shield_steps(
        .d(r_seq_shield_steps$d),
        .q(r_seq_shield_steps$q),
        .clock(r_seq_shield_steps$clock)
    );
    skylux_core$regs$r_seq_shield_step_period r_seq_shield_step_period(
        .d(r_seq_shield_step_period$d),
        .q(r_seq_shield_step_period$q),
        .clock(r_seq_shield_step_period$clock)
    );
    skylux_core$regs$r_seq_trigger_pulse r_seq_trigger_pulse(
        .d(r_seq_trigger_pulse$d),
        .q(r_seq_trigger_pulse$q),
        .clock(r_seq_trigger_pulse$clock)
    );
    skylux_core$regs$r_seq_exp_shutter_width_0 r_seq_exp_shutter_width_0(
        .d(r_seq_exp_shutter_width_0$d),
        .q(r_seq_exp_shutter_width_0$q),
        .clock(r_seq_exp_shutter_width_0$clock)
    );
    skylux_core$regs$r_seq_exp_shutter_width_1 r_seq_exp_shutter_width_1(
        .d(r_seq_exp_shutter_width_1$d),
        .q(r_seq_exp_shutter_width_1$q),
        .clock(r_seq_exp_shutter_width_1$clock)
    );
    skylux_core$regs$r_seq_exp_shutter_width_2 r_seq_exp_shutter_width_2(
        .d(r_seq_exp_shutter_width_2$d),
        .q(r_seq_exp_shutter_width_2$q),
        .clock(r_seq_exp_shutter_width_2$clock)
    );
    skylux_core$regs$r_seq_exp_shutter_width_3 r_seq_exp_shutter_width_3(
        .d(r_seq_exp_shutter_width_3$d),
        .q(r_seq_exp_shutter_width_3$q),
        .clock(r_seq_exp_shutter_width_3$clock)
    );
    skylux_core$regs$r_seq_exp_shutter_width_4 r_seq_exp_shutter_width_4(
        .d(r_seq_exp_shutter_width_4$d),
        .q(r_seq_exp_shutter_width_4$q),
        .clock(r_seq_exp_shutter_width_4$clock)
    );
    skylux_core$regs$r_seq_exp_shutter_width_5 r_seq_exp_shutter_width_5(
        .d(r_seq_exp_shutter_width_5$d),
        .q(r_seq_exp_shutter_width_5$q),
        .clock(r_seq_exp_shutter_width_5$clock)
    );
    skylux_core$regs$r_seq_exp_shutter_width_6 r_seq_exp_shutter_width_6(
        .d(r_seq_exp_shutter_width_6$d),
        .q(r_seq_exp_shutter_width_6$q),
        .clock(r_seq_exp_shutter_width_6$clock)
    );
    skylux_core$regs$r_seq_exp_shutter_width_7 r_seq_exp_shutter_width_7(
        .d(r_seq_exp_shutter_width_7$d),
        .q(r_seq_exp_shutter_width_7$q),
        .clock(r_seq_exp_shutter_width_7$clock)
    );
    skylux_core$regs$r_seq_exp_shutter_delay_0 r_seq_exp_shutter_delay_0(
        .d(r_seq_exp_shutter_delay_0$d),
        .q(r_seq_exp_shutter_delay_0$q),
        .clock(r_seq_exp_shutter_delay_0$clock)
    );
    skylux_core$regs$r_seq_exp_shutter_delay_1 r_seq_exp_shutter_delay_1(
        .d(r_seq_exp_shutter_delay_1$d),
        .q(r_seq_exp_shutter_delay_1$q),
        .clock(r_seq_exp_shutter_delay_1$clock)
    );
    skylux_core$regs$r_seq_exp_shutter_delay_2 r_seq_exp_shutter_delay_2(
        .d(r_seq_exp_shutter_delay_2$d),
        .q(r_seq_exp_shutter_delay_2$q),
        .clock(r_seq_exp_shutter_delay_2$clock)
    );
    skylux_core$regs$r_seq_exp_shutter_delay_3 r_seq_exp_shutter_delay_3(
        .d(r_seq_exp_shutter_delay_3$d),
        .q(r_seq_exp_shutter_delay_3$q),
        .clock(r_seq_exp_shutter_delay_3$clock)
    );
    skylux_core$regs$r_seq_exp_shutter_delay_4 r_seq_exp_shutter_delay_4(
        .d(r_seq_exp_shutter_delay_4$d),
        .q(r_seq_exp_shutter_delay_4$q),
        .clock(r_seq_exp_shutter_delay_4$clock)
    );
    skylux_core$regs$r_seq_exp_shutter_delay_5 r_seq_exp_shutter_delay_5(
        .d(r_seq_exp_shutter_delay_5$d),
        .q(r_seq_exp_shutter_delay_5$q),
        .clock(r_seq_exp_shutter_delay_5$clock)
    );
    skylux_core$regs$r_seq_exp_shutter_delay_6 r_seq_exp_shutter_delay_6(
        .d(r_seq_exp_shutter_delay_6$d),
        .q(r_seq_exp_shutter_delay_6$q),
        .clock(r_seq_exp_shutter_delay_6$clock)
    );
    skylux_core$regs$r_seq_exp_shutter_delay_7 r_seq_exp_shutter_delay_7(
        .d(r_seq_exp_shutter_delay_7$d),
        .q(r_seq_exp_shutter_delay_7$q),
        .clock(r_seq_exp_shutter_delay_7$clock)
    );
    skylux_core$regs$r_seq_exp_gain_0 r_seq_exp_gain_0(
        .d(r_seq_exp_gain_0$d),
        .q(r_seq_exp_gain_0$q),
        .clock(r_seq_exp_gain_0$clock)
    );
    skylux_core$regs$r_seq_exp_gain_1 r_seq_exp_gain_1(
        .d(r_seq_exp_gain_1$d),
        .q(r_seq_exp_gain_1$q),
        .clock(r_seq_exp_gain_1$clock)
    );
    skylux_core$regs$r_seq_exp_gain_2 r_seq_exp_gain_2(
        .d(r_seq_exp_gain_2$d),
        .q(r_seq_exp_gain_2$q),
        .clock(r_seq_exp_gain_2$clock)
    );
    skylux_core$regs$r_seq_exp_gain_3 r_seq_exp_gain_3(
        .d(r_seq_exp_gain_3$d),
        .q(r_seq_exp_gain_3$q),
        .clock(r_seq_exp_gain_3$clock)
    );
    skylux_core$regs$r_seq_exp_gain_4 r_seq_exp_gain_4(
        .d(r_seq_exp_gain_4$d),
        .q(r_seq_exp_gain_4$q),
        .clock(r_seq_exp_gain_4$clock)
    );
    skylux_core$regs$r_seq_exp_gain_5 r_seq_exp_gain_5(
        .d(r_seq_exp_gain_5$d),
        .q(r_seq_exp_gain_5$q),
        .clock(r_seq_exp_gain_5$clock)
    );
    skylux_core$regs$r_seq_exp_gain_6 r_seq_exp_gain_6(
        .d(r_seq_exp_gain_6$d),
        .q(r_seq_exp_gain_6$q),
        .clock(r_seq_exp_gain_6$clock)
    );
    skylux_core$regs$r_seq_exp_gain_7 r_seq_exp_gain_7(
        .d(r_seq_exp_gain_7$d),
        .q(r_seq_exp_gain_7$q),
        .clock(r_seq_exp_gain_7$clock)
    );
    skylux_core$regs$r_capture_ctrl r_capture_ctrl(
        .d(r_capture_ctrl$d),
        .q(r_capture_ctrl$q),
        .clock(r_capture_ctrl$clock)
    );
    skylux_core$regs$r_capture_window r_capture_window(
        .d(r_capture_window$d),
        .q(r_capture_window$q),
        .clock(r_capture_window$clock)
    );
    skylux_core$regs$r_capture_status r_capture_status(
        .d(r_capture_status$d),
        .q(r_capture_status$q),
        .clock(r_capture_status$clock)
    );
    skylux_core$regs$r_bayer_mode r_bayer_mode(
        .d(r_bayer_mode$d),
        .q(r_bayer_mode$q),
        .clock(r_bayer_mode$clock)
    );
    skylux_core$regs$r_bayer_black r_bayer_black(
        .d(r_bayer_black$d),
        .q(r_bayer_black$q),
        .clock(r_bayer_black$clock)
    );
    skylux_core$regs$r_bayer_valid r_bayer_valid(
        .d(r_bayer_valid$d),
        .q(r_bayer_valid$q),
        .clock(r_bayer_valid$clock)
    );
    skylux_core$regs$r_bayer_weight_r r_bayer_weight_r(
        .d(r_bayer_weight_r$d),
        .q(r_bayer_weight_r$q),
        .clock(r_bayer_weight_r$clock)
    );
    skylux_core$regs$r_bayer_weight_g r_bayer_weight_g(
        .d(r_bayer_weight_g$d),
        .q(r_bayer_weight_g$q),
        .clock(r_bayer_weight_g$clock)
    );
    skylux_core$regs$r_bayer_weight_b r_bayer_weight_b(
        .d(r_bayer_weight_b$d),
        .q(r_bayer_weight_b$q),
        .clock(r_bayer_weight_b$clock)
    );
    skylux_core$regs$r_dma_ctrl r_dma_ctrl(
        .d(r_dma_ctrl$d),
        .q(r_dma_ctrl$q),
        .clock(r_dma_ctrl$clock)
    );
    skylux_core$regs$p_dma_ctrl p_dma_ctrl(
        .d(p_dma_ctrl$d),
        .q(p_dma_ctrl$q),
        .clock(p_dma_ctrl$clock)
    );
    skylux_core$regs$r_dma_window_base r_dma_window_base(
        .d(r_dma_window_base$d),
        .q(r_dma_window_base$q),
        .clock(r_dma_window_base$clock)
    );
    skylux_core$regs$r_dma_window_size r_dma_window_size(
        .d(r_dma_window_size$d),
        .q(r_dma_window_size$q),
        .clock(r_dma_window_size$clock)
    );
    skylux_core$regs$r_dma_slot_stride r_dma_slot_stride(
        .d(r_dma_slot_stride$d),
        .q(r_dma_slot_stride$q),
        .clock(r_dma_slot_stride$clock)
    );
    skylux_core$regs$r_dma_slots r_dma_slots(
        .d(r_dma_slots$d),
        .q(r_dma_slots$q),
        .clock(r_dma_slots$clock)
    );
    skylux_core$regs$r_dma_status r_dma_status(
        .d(r_dma_status$d),
        .q(r_dma_status$q),
        .clock(r_dma_status$clock)
    );
    skylux_core$regs$r_dma_bus_timeout r_dma_bus_timeout(
        .d(r_dma_bus_timeout$d),
        .q(r_dma_bus_timeout$q),
        .clock(r_dma_bus_timeout$clock)
    );
    skylux_core$regs$p_raybox_ctrl p_raybox_ctrl(
        .d(p_raybox_ctrl$d),
        .q(p_raybox_ctrl$q),
        .clock(p_raybox_ctrl$clock)
    );
    skylux_core$regs$r_raybox_work_base r_raybox_work_base(
        .d(r_raybox_work_base$d),
        .q(r_raybox_work_base$q),
        .clock(r_raybox_work_base$clock)
    );
    skylux_core$regs$r_raybox_work_count r_raybox_work_count(
        .d(r_raybox_work_count$d),
        .q(r_raybox_work_count$q),
        .clock(r_raybox_work_count$clock)
    );
    skylux_core$regs$r_raybox_result_base r_raybox_result_base(
        .d(r_raybox_result_base$d),
        .q(r_raybox_result_base$q),
        .clock(r_raybox_result_base$clock)
    );
    skylux_core$regs$r_raybox_window_base r_raybox_window_base(
        .d(r_raybox_window_base$d),
        .q(r_raybox_window_base$q),
        .clock(r_raybox_window_base$clock)
    );
    skylux_core$regs$r_raybox_window_size r_raybox_window_size(
        .d(r_raybox_window_size$d),
        .q(r_raybox_window_size$q),
        .clock(r_raybox_window_size$clock)
    );
    skylux_core$regs$r_raybox_status r_raybox_status(
        .d(r_raybox_status$d),
        .q(r_raybox_status$q),
        .clock(r_raybox_status$clock)
    );
    skylux_core$regs$r_raybox_bus_timeout r_raybox_bus_timeout(
        .d(r_raybox_bus_timeout$d),
        .q(r_raybox_bus_timeout$q),
        .clock(r_raybox_bus_timeout$clock)
    );
    skylux_core$regs$r_sun_ctrl r_sun_ctrl(
        .d(r_sun_ctrl$d),
        .q(r_sun_ctrl$q),
        .clock(r_sun_ctrl$clock)
    );
    skylux_core$regs$r_sun_threshold r_sun_threshold(
        .d(r_sun_threshold$d),
        .q(r_sun_threshold$q),
        .clock(r_sun_threshold$clock)
    );
    skylux_core$regs$r_sun_window_x r_sun_window_x(
        .d(r_sun_window_x$d),
        .q(r_sun_window_x$q),
        .clock(r_sun_window_x$clock)
    );
    skylux_core$regs$r_sun_window_y r_sun_window_y(
        .d(r_sun_window_y$d),
        .q(r_sun_window_y$q),
        .clock(r_sun_window_y$clock)
    );
    skylux_core$regs$r_hdr_ctrl r_hdr_ctrl(
        .d(r_hdr_ctrl$d),
        .q(r_hdr_ctrl$q),
        .clock(r_hdr_ctrl$clock)
    );
    skylux_core$regs$p_hdr_ctrl p_hdr_ctrl(
        .d(p_hdr_ctrl$d),
        .q(p_hdr_ctrl$q),
        .clock(p_hdr_ctrl$clock)
    );
    skylux_core$regs$r_hdr_min r_hdr_min(
        .d(r_hdr_min$d),
        .q(r_hdr_min$q),
        .clock(r_hdr_min$clock)
    );
    skylux_core$regs$r_hdr_max r_hdr_max(
        .d(r_hdr_max$d),
        .q(r_hdr_max$q),
        .clock(r_hdr_max$clock)
    );
    
    // Update code
    always @(*) begin
        rdata$clock = clock;
        error_word$clock = clock;
        r_sys_scratch$clock = clock;
        r_sys_bus_status$clock = clock;
        r_sys_irq_status$clock = clock;
        r_sys_irq_enable$clock = clock;
        r_i2c_ctrl$clock = clock;
        p_i2c_ctrl$clock = clock;
        r_i2c_target$clock = clock;
        r_i2c_reg_addr$clock = clock;
        r_i2c_write_data$clock = clock;
        r_i2c_status$clock = clock;
        r_i2c_clock_div$clock = clock;
        r_i2c_timeout$clock = clock;
        r_i2c_sensor_pins$clock = clock;
        r_seq_ctrl$clock = clock;
        p_seq_ctrl$clock = clock;
        r_seq_count$clock = clock;
        r_seq_status$clock = clock;
        r_seq_shield_limit$clock = clock;
        r_seq_shield_steps$clock = clock;
        r_seq_shield_step_period$clock = clock;
        r_seq_trigger_pulse$clock = clock;
        r_seq_exp_shutter_width_0$clock = clock;
        r_seq_exp_shutter_width_1$clock = clock;
        r_seq_exp_shutter_width_2$clock = clock;
        r_seq_exp_shutter_width_3$clock = clock;
        r_seq_exp_shutter_width_4$clock = clock;
        r_seq_exp_shutter_width_5$clock = clock;
        r_seq_exp_shutter_width_6$clock = clock;
        r_seq_exp_shutter_width_7$clock = clock;
        r_seq_exp_shutter_delay_0$clock = clock;
        r_seq_exp_shutter_delay_1$clock = clock;
        r_seq_exp_shutter_delay_2$clock = clock;
        r_seq_exp_shutter_delay_3$clock = clock;
        r_seq_exp_shutter_delay_4$clock = clock;
        r_seq_exp_shutter_delay_5$clock = clock;
        r_seq_exp_shutter_delay_6$clock = clock;
        r_seq_exp_shutter_delay_7$clock = clock;
        r_seq_exp_gain_0$clock = clock;
        r_seq_exp_gain_1$clock = clock;
        r_seq_exp_gain_2$clock = clock;
        r_seq_exp_gain_3$clock = clock;
        r_seq_exp_gain_4$clock = clock;
        r_seq_exp_gain_5$clock = clock;
        r_seq_exp_gain_6$clock = clock;
        r_seq_exp_gain_7$clock = clock;
        r_capture_ctrl$clock = clock;
        r_capture_window$clock = clock;
        r_capture_status$clock = clock;
        r_bayer_mode$clock = clock;
        r_bayer_black$clock = clock;
        r_bayer_valid$clock = clock;
        r_bayer_weight_r$clock = clock;
        r_bayer_weight_g$clock = clock;
        r_bayer_weight_b$clock = clock;
        r_dma_ctrl$clock = clock;
        p_dma_ctrl$clock = clock;
        r_dma_window_base$clock = clock;
        r_dma_window_size$clock = clock;
        r_dma_slot_stride$clock = clock;
        r_dma_slots$clock = clock;
        r_dma_status$clock = clock;
        r_dma_bus_timeout$clock = clock;
        p_raybox_ctrl$clock = clock;
        r_raybox_work_base$clock = clock;
        r_raybox_work_count$clock = clock;
        r_raybox_result_base$clock = clock;
        r_raybox_window_base$clock = clock;
        r_raybox_window_size$clock = clock;
        r_raybox_status$clock = clock;
        r_raybox_bus_timeout$clock = clock;
        r_sun_ctrl$clock = clock;
        r_sun_threshold$clock = clock;
        r_sun_window_x$clock = clock;
        r_sun_window_y$clock = clock;
        r_hdr_ctrl$clock = clock;
        p_hdr_ctrl$clock = clock;
        r_hdr_min$clock = clock;
        r_hdr_max$clock = clock;
        rdata$d = rdata$q;
        error_word$d = error_word$q;
        r_sys_scratch$d = r_sys_scratch$q;
        r_sys_bus_status$d = r_sys_bus_status$q;
        r_sys_irq_status$d = r_sys_irq_status$q;
        r_sys_irq_enable$d = r_sys_irq_enable$q;
        r_i2c_ctrl$d = r_i2c_ctrl$q;
        p_i2c_ctrl$d = p_i2c_ctrl$q;
        r_i2c_target$d = r_i2c_target$q;
        r_i2c_reg_addr$d = r_i2c_reg_addr$q;
        r_i2c_write_data$d = r_i2c_write_data$q;
        r_i2c_status$d = r_i2c_status$q;
        r_i2c_clock_div$d = r_i2c_clock_div$q;
        r_i2c_timeout$d = r_i2c_timeout$q;
        r_i2c_sensor_pins$d = r_i2c_sensor_pins$q;
        r_seq_ctrl$d = r_seq_ctrl$q;
        p_seq_ctrl$d = p_seq_ctrl$q;
        r_seq_count$d = r_seq_count$q;
        r_seq_status$d = r_seq_status$q;
        r_seq_shield_limit$d = r_seq_shield_limit$q;
        r_seq_shield_steps$d = r_seq_shield_steps$q;
        r_seq_shield_step_period$d = r_seq_shield_step_period$q;
        r_seq_trigger_pulse$d = r_seq_trigger_pulse$q;
        r_seq_exp_shutter_width_0$d = r_seq_exp_shutter_width_0$q;
        r_seq_exp_shutter_width_1$d = r_seq_exp_shutter_width_1$q;
        r_seq_exp_shutter_width_2$d = r_seq_exp_shutter_width_2$q;
        r_seq_exp_shutter_width_3$d = r_seq_exp_shutter_width_3$q;
        r_seq_exp_shutter_width_4$d = r_seq_exp_shutter_width_4$q;
        r_seq_exp_shutter_width_5$d = r_seq_exp_shutter_width_5$q;
        r_seq_exp_shutter_width_6$d = r_seq_exp_shutter_width_6$q;
        r_seq_exp_shutter_width_7$d = r_seq_exp_shutter_width_7$q;
        r_seq_exp_shutter_delay_0$d = r_seq_exp_shutter_delay_0$q;
        r_seq_exp_shutter_delay_1$d = r_seq_exp_shutter_delay_1$q;
        r_seq_exp_shutter_delay_2$d = r_seq_exp_shutter_delay_2$q;
        r_seq_exp_shutter_delay_3$d = r_seq_exp_shutter_delay_3$q;
        r_seq_exp_shutter_delay_4$d = r_seq_exp_shutter_delay_4$q;
        r_seq_exp_shutter_delay_5$d = r_seq_exp_shutter_delay_5$q;
        r_seq_exp_shutter_delay_6$d = r_seq_exp_shutter_delay_6$q;
        r_seq_exp_shutter_delay_7$d = r_seq_exp_shutter_delay_7$q;
        r_seq_exp_gain_0$d = r_seq_exp_gain_0$q;
        r_seq_exp_gain_1$d = r_seq_exp_gain_1$q;
        r_seq_exp_gain_2$d = r_seq_exp_gain_2$q;
        r_seq_exp_gain_3$d = r_seq_exp_gain_3$q;
        r_seq_exp_gain_4$d = r_seq_exp_gain_4$q;
        r_seq_exp_gain_5$d = r_seq_exp_gain_5$q;
        r_seq_exp_gain_6$d = r_seq_exp_gain_6$q;
        r_seq_exp_gain_7$d = r_seq_exp_gain_7$q;
        r_capture_ctrl$d = r_capture_ctrl$q;
        r_capture_window$d = r_capture_window$q;
        r_capture_status$d = r_capture_status$q;
        r_bayer_mode$d = r_bayer_mode$q;
        r_bayer_black$d = r_bayer_black$q;
        r_bayer_valid$d = r_bayer_valid$q;
        r_bayer_weight_r$d = r_bayer_weight_r$q;
        r_bayer_weight_g$d = r_bayer_weight_g$q;
        r_bayer_weight_b$d = r_bayer_weight_b$q;
        r_dma_ctrl$d = r_dma_ctrl$q;
        p_dma_ctrl$d = p_dma_ctrl$q;
        r_dma_window_base$d = r_dma_window_base$q;
        r_dma_window_size$d = r_dma_window_size$q;
        r_dma_slot_stride$d = r_dma_slot_stride$q;
        r_dma_slots$d = r_dma_slots$q;
        r_dma_status$d = r_dma_status$q;
        r_dma_bus_timeout$d = r_dma_bus_timeout$q;
        p_raybox_ctrl$d = p_raybox_ctrl$q;
        r_raybox_work_base$d = r_raybox_work_base$q;
        r_raybox_work_count$d = r_raybox_work_count$q;
        r_raybox_result_base$d = r_raybox_result_base$q;
        r_raybox_window_base$d = r_raybox_window_base$q;
        r_raybox_window_size$d = r_raybox_window_size$q;
        r_raybox_status$d = r_raybox_status$q;
        r_raybox_bus_timeout$d = r_raybox_bus_timeout$q;
        r_sun_ctrl$d = r_sun_ctrl$q;
        r_sun_threshold$d = r_sun_threshold$q;
        r_sun_window_x$d = r_sun_window_x$q;
        r_sun_window_y$d = r_sun_window_y$q;
        r_hdr_ctrl$d = r_hdr_ctrl$q;
        p_hdr_ctrl$d = p_hdr_ctrl$q;
        r_hdr_min$d = r_hdr_min$q;
        r_hdr_max$d = r_hdr_max$q;
        byte_mask = 32'h0;
        if (avs_byteenable[0]) begin
            byte_mask = byte_mask | (((64'hff) & 32'hffffffff) << (32'h8 * 0));
        end
        if (avs_byteenable[1]) begin
            byte_mask = byte_mask | (((64'hff) & 32'hffffffff) << (32'h8 * 1));
        end
        if (avs_byteenable[2]) begin
            byte_mask = byte_mask | (((64'hff) & 32'hffffffff) << (32'h8 * 2));
        end
        if (avs_byteenable[3]) begin
            byte_mask = byte_mask | (((64'hff) & 32'hffffffff) << (32'h8 * 3));
        end
        unmapped_read = 1'b0;
        unmapped_write = 1'b0;
        nx_sys_scratch = r_sys_scratch$q;
        nx_sys_bus_status = r_sys_bus_status$q;
        nx_sys_irq_status = r_sys_irq_status$q;
        nx_sys_irq_enable = r_sys_irq_enable$q;
        nx_i2c_ctrl = r_i2c_ctrl$q;
        p_i2c_ctrl$d = 32'h0;
        nx_i2c_target = r_i2c_target$q;
        nx_i2c_reg_addr = r_i2c_reg_addr$q;
        nx_i2c_write_data = r_i2c_write_data$q;
        nx_i2c_status = r_i2c_status$q;
        nx_i2c_clock_div = r_i2c_clock_div$q;
        nx_i2c_timeout = r_i2c_timeout$q;
        nx_i2c_sensor_pins = r_i2c_sensor_pins$q;
        nx_seq_ctrl = r_seq_ctrl$q;
        p_seq_ctrl$d = 32'h0;
        nx_seq_count = r_seq_count$q;
        nx_seq_status = r_seq_status$q;
        nx_seq_shield_limit = r_seq_shield_limit$q;
        nx_seq_shield_steps = r_seq_shield_steps$q;
        nx_seq_shield_step_period = r_seq_shield_step_period$q;
        nx_seq_trigger_pulse = r_seq_trigger_pulse$q;
        nx_seq_exp_shutter_width_0 = r_seq_exp_shutter_width_0$q;
        nx_seq_exp_shutter_width_1 = r_seq_exp_shutter_width_1$q;
        nx_seq_exp_shutter_width_2 = r_seq_exp_shutter_width_2$q;
        nx_seq_exp_shutter_width_3 = r_seq_exp_shutter_width_3$q;
        nx_seq_exp_shutter_width_4 = r_seq_exp_shutter_width_4$q;
        nx_seq_exp_shutter_width_5 = r_seq_exp_shutter_width_5$q;
        nx_seq_exp_shutter_width_6 = r_seq_exp_shutter_width_6$q;
        nx_seq_exp_shutter_width_7 = r_seq_exp_shutter_width_7$q;
        nx_seq_exp_shutter_delay_0 = r_seq_exp_shutter_delay_0$q;
        nx_seq_exp_shutter_delay_1 = r_seq_exp_shutter_delay_1$q;
        nx_seq_exp_shutter_delay_2 = r_seq_exp_shutter_delay_2$q;
        nx_seq_exp_shutter_delay_3 = r_seq_exp_shutter_delay_3$q;
        nx_seq_exp_shutter_delay_4 = r_seq_exp_shutter_delay_4$q;
        nx_seq_exp_shutter_delay_5 = r_seq_exp_shutter_delay_5$q;
        nx_seq_exp_shutter_delay_6 = r_seq_exp_shutter_delay_6$q;
        nx_seq_exp_shutter_delay_7 = r_seq_exp_shutter_delay_7$q;
        nx_seq_exp_gain_0 = r_seq_exp_gain_0$q;
        nx_seq_exp_gain_1 = r_seq_exp_gain_1$q;
        nx_seq_exp_gain_2 = r_seq_exp_gain_2$q;
        nx_seq_exp_gain_3 = r_seq_exp_gain_3$q;
        nx_seq_exp_gain_4 = r_seq_exp_gain_4$q;
        nx_seq_exp_gain_5 = r_seq_exp_gain_5$q;
        nx_seq_exp_gain_6 = r_seq_exp_gain_6$q;
        nx_seq_exp_gain_7 = r_seq_exp_gain_7$q;
        nx_capture_ctrl = r_capture_ctrl$q;
        nx_capture_window = r_capture_window$q;
        nx_capture_status = r_capture_status$q;
        nx_bayer_mode = r_bayer_mode$q;
        nx_bayer_black = r_bayer_black$q;
        nx_bayer_valid = r_bayer_valid$q;
        nx_bayer_weight_r = r_bayer_weight_r$q;
        nx_bayer_weight_g = r_bayer_weight_g$q;
        nx_bayer_weight_b = r_bayer_weight_b$q;
        nx_dma_ctrl = r_dma_ctrl$q;
        p_dma_ctrl$d = 32'h0;
        nx_dma_window_base = r_dma_window_base$q;
        nx_dma_window_size = r_dma_window_size$q;
        nx_dma_slot_stride = r_dma_slot_stride$q;
        nx_dma_slots = r_dma_slots$q;
        nx_dma_status = r_dma_status$q;
        nx_dma_bus_timeout = r_dma_bus_timeout$q;
        p_raybox_ctrl$d = 32'h0;
        nx_raybox_work_base = r_raybox_work_base$q;
        nx_raybox_work_count = r_raybox_work_count$q;
        nx_raybox_result_base = r_raybox_result_base$q;
        nx_raybox_window_base = r_raybox_window_base$q;
        nx_raybox_window_size = r_raybox_window_size$q;
        nx_raybox_status = r_raybox_status$q;
        nx_raybox_bus_timeout = r_raybox_bus_timeout$q;
        nx_sun_ctrl = r_sun_ctrl$q;
        nx_sun_threshold = r_sun_threshold$q;
        nx_sun_window_x = r_sun_window_x$q;
        nx_sun_window_y = r_sun_window_y$q;
        nx_hdr_ctrl = r_hdr_ctrl$q;
        p_hdr_ctrl$d = 32'h0;
        nx_hdr_min = r_hdr_min$q;
        nx_hdr_max = r_hdr_max$q;
        if (avs_write) begin
            case (avs_address)
                0:
                    begin
                    end
                1:
                    begin
                    end
                2:
                    begin
                        nx_sys_scratch = ((r_sys_scratch$q & (~(byte_mask & 64'hffffffff))) | (avs_writedata & (byte_mask & 64'hffffffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                3:
                    begin
                        nx_sys_bus_status = ((r_sys_bus_status$q & (~(byte_mask & 64'h0))) | (avs_writedata & (byte_mask & 64'h0))) & (~(avs_writedata & (byte_mask & 64'h3)));
                    end
                4:
                    begin
                    end
                5:
                    begin
                    end
                6:
                    begin
                    end
                7:
                    begin
                    end
                8:
                    begin
                        nx_sys_irq_status = ((r_sys_irq_status$q & (~(byte_mask & 64'h0))) | (avs_writedata & (byte_mask & 64'h0))) & (~(avs_writedata & (byte_mask & 64'h3f)));
                    end
                9:
                    begin
                        nx_sys_irq_enable = ((r_sys_irq_enable$q & (~(byte_mask & 64'h3f))) | (avs_writedata & (byte_mask & 64'h3f))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                1024:
                    begin
                        nx_i2c_ctrl = ((r_i2c_ctrl$q & (~(byte_mask & 64'h2))) | (avs_writedata & (byte_mask & 64'h2))) & (~(avs_writedata & (byte_mask & 64'h0)));
                        p_i2c_ctrl$d = avs_writedata & (byte_mask & 64'h1);
                    end
                1025:
                    begin
                        nx_i2c_target = ((r_i2c_target$q & (~(byte_mask & 64'h7f))) | (avs_writedata & (byte_mask & 64'h7f))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                1026:
                    begin
                        nx_i2c_reg_addr = ((r_i2c_reg_addr$q & (~(byte_mask & 64'hff))) | (avs_writedata & (byte_mask & 64'hff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                1027:
                    begin
                        nx_i2c_write_data = ((r_i2c_write_data$q & (~(byte_mask & 64'hffff))) | (avs_writedata & (byte_mask & 64'hffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                1028:
                    begin
                    end
                1029:
                    begin
                        nx_i2c_status = ((r_i2c_status$q & (~(byte_mask & 64'h0))) | (avs_writedata & (byte_mask & 64'h0))) & (~(avs_writedata & (byte_mask & 64'h3e)));
                    end
                1030:
                    begin
                        nx_i2c_clock_div = ((r_i2c_clock_div$q & (~(byte_mask & 64'hffff))) | (avs_writedata & (byte_mask & 64'hffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                1031:
                    begin
                        nx_i2c_timeout = ((r_i2c_timeout$q & (~(byte_mask & 64'hffffff))) | (avs_writedata & (byte_mask & 64'hffffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                1032:
                    begin
                        nx_i2c_sensor_pins = ((r_i2c_sensor_pins$q & (~(byte_mask & 64'h1))) | (avs_writedata & (byte_mask & 64'h1))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                2048:
                    begin
                        nx_seq_ctrl = ((r_seq_ctrl$q & (~(byte_mask & 64'h4))) | (avs_writedata & (byte_mask & 64'h4))) & (~(avs_writedata & (byte_mask & 64'h0)));
                        p_seq_ctrl$d = avs_writedata & (byte_mask & 64'h3);
                    end
                2049:
                    begin
                        nx_seq_count = ((r_seq_count$q & (~(byte_mask & 64'hf))) | (avs_writedata & (byte_mask & 64'hf))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                2050:
                    begin
                        nx_seq_status = ((r_seq_status$q & (~(byte_mask & 64'h0))) | (avs_writedata & (byte_mask & 64'h0))) & (~(avs_writedata & (byte_mask & 64'h1f0000)));
                    end
                2051:
                    begin
                        nx_seq_shield_limit = ((r_seq_shield_limit$q & (~(byte_mask & 64'hffffffff))) | (avs_writedata & (byte_mask & 64'hffffffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                2052:
                    begin
                        nx_seq_shield_steps = ((r_seq_shield_steps$q & (~(byte_mask & 64'hffff))) | (avs_writedata & (byte_mask & 64'hffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                2053:
                    begin
                        nx_seq_shield_step_period = ((r_seq_shield_step_period$q & (~(byte_mask & 64'hffffff))) | (avs_writedata & (byte_mask & 64'hffffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                2054:
                    begin
                    end
                2055:
                    begin
                        nx_seq_trigger_pulse = ((r_seq_trigger_pulse$q & (~(byte_mask & 64'hffff))) | (avs_writedata & (byte_mask & 64'hffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                2064:
                    begin
                        nx_seq_exp_shutter_width_0 = ((r_seq_exp_shutter_width_0$q & (~(byte_mask & 64'hfffff))) | (avs_writedata & (byte_mask & 64'hfffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                2065:
                    begin
                        nx_seq_exp_shutter_width_1 = ((r_seq_exp_shutter_width_1$q & (~(byte_mask & 64'hfffff))) | (avs_writedata & (byte_mask & 64'hfffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                2066:
                    begin
                        nx_seq_exp_shutter_width_2 = ((r_seq_exp_shutter_width_2$q & (~(byte_mask & 64'hfffff))) | (avs_writedata & (byte_mask & 64'hfffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                2067:
                    begin
                        nx_seq_exp_shutter_width_3 = ((r_seq_exp_shutter_width_3$q & (~(byte_mask & 64'hfffff))) | (avs_writedata & (byte_mask & 64'hfffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                2068:
                    begin
                        nx_seq_exp_shutter_width_4 = ((r_seq_exp_shutter_width_4$q & (~(byte_mask & 64'hfffff))) | (avs_writedata & (byte_mask & 64'hfffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                2069:
                    begin
                        nx_seq_exp_shutter_width_5 = ((r_seq_exp_shutter_width_5$q & (~(byte_mask & 64'hfffff))) | (avs_writedata & (byte_mask & 64'hfffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                2070:
                    begin
                        nx_seq_exp_shutter_width_6 = ((r_seq_exp_shutter_width_6$q & (~(byte_mask & 64'hfffff))) | (avs_writedata & (byte_mask & 64'hfffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                2071:
                    begin
                        nx_seq_exp_shutter_width_7 = ((r_seq_exp_shutter_width_7$q & (~(byte_mask & 64'hfffff))) | (avs_writedata & (byte_mask & 64'hfffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                2072:
                    begin
                        nx_seq_exp_shutter_delay_0 = ((r_seq_exp_shutter_delay_0$q & (~(byte_mask & 64'h1fff))) | (avs_writedata & (byte_mask & 64'h1fff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                2073:
                    begin
                        nx_seq_exp_shutter_delay_1 = ((r_seq_exp_shutter_delay_1$q & (~(byte_mask & 64'h1fff))) | (avs_writedata & (byte_mask & 64'h1fff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                2074:
                    begin
                        nx_seq_exp_shutter_delay_2 = ((r_seq_exp_shutter_delay_2$q & (~(byte_mask & 64'h1fff))) | (avs_writedata & (byte_mask & 64'h1fff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                2075:
                    begin
                        nx_seq_exp_shutter_delay_3 = ((r_seq_exp_shutter_delay_3$q & (~(byte_mask & 64'h1fff))) | (avs_writedata & (byte_mask & 64'h1fff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                2076:
                    begin
                        nx_seq_exp_shutter_delay_4 = ((r_seq_exp_shutter_delay_4$q & (~(byte_mask & 64'h1fff))) | (avs_writedata & (byte_mask & 64'h1fff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                2077:
                    begin
                        nx_seq_exp_shutter_delay_5 = ((r_seq_exp_shutter_delay_5$q & (~(byte_mask & 64'h1fff))) | (avs_writedata & (byte_mask & 64'h1fff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                2078:
                    begin
                        nx_seq_exp_shutter_delay_6 = ((r_seq_exp_shutter_delay_6$q & (~(byte_mask & 64'h1fff))) | (avs_writedata & (byte_mask & 64'h1fff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                2079:
                    begin
                        nx_seq_exp_shutter_delay_7 = ((r_seq_exp_shutter_delay_7$q & (~(byte_mask & 64'h1fff))) | (avs_writedata & (byte_mask & 64'h1fff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                2080:
                    begin
                        nx_seq_exp_gain_0 = ((r_seq_exp_gain_0$q & (~(byte_mask & 64'hffff))) | (avs_writedata & (byte_mask & 64'hffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                2081:
                    begin
                        nx_seq_exp_gain_1 = ((r_seq_exp_gain_1$q & (~(byte_mask & 64'hffff))) | (avs_writedata & (byte_mask & 64'hffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                2082:
                    begin
                        nx_seq_exp_gain_2 = ((r_seq_exp_gain_2$q & (~(byte_mask & 64'hffff))) | (avs_writedata & (byte_mask & 64'hffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                2083:
                    begin
                        nx_seq_exp_gain_3 = ((r_seq_exp_gain_3$q & (~(byte_mask & 64'hffff))) | (avs_writedata & (byte_mask & 64'hffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                2084:
                    begin
                        nx_seq_exp_gain_4 = ((r_seq_exp_gain_4$q & (~(byte_mask & 64'hffff))) | (avs_writedata & (byte_mask & 64'hffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                2085:
                    begin
                        nx_seq_exp_gain_5 = ((r_seq_exp_gain_5$q & (~(byte_mask & 64'hffff))) | (avs_writedata & (byte_mask & 64'hffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                2086:
                    begin
                        nx_seq_exp_gain_6 = ((r_seq_exp_gain_6$q & (~(byte_mask & 64'hffff))) | (avs_writedata & (byte_mask & 64'hffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                2087:
                    begin
                        nx_seq_exp_gain_7 = ((r_seq_exp_gain_7$q & (~(byte_mask & 64'hffff))) | (avs_writedata & (byte_mask & 64'hffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                3072:
                    begin
                        nx_capture_ctrl = ((r_capture_ctrl$q & (~(byte_mask & 64'h3))) | (avs_writedata & (byte_mask & 64'h3))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                3073:
                    begin
                        nx_capture_window = ((r_capture_window$q & (~(byte_mask & 64'hfff0fff))) | (avs_writedata & (byte_mask & 64'hfff0fff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                3074:
                    begin
                        nx_capture_status = ((r_capture_status$q & (~(byte_mask & 64'h0))) | (avs_writedata & (byte_mask & 64'h0))) & (~(avs_writedata & (byte_mask & 64'h3f00)));
                    end
                3075:
                    begin
                    end
                3076:
                    begin
                    end
                3077:
                    begin
                    end
                4096:
                    begin
                        nx_bayer_mode = ((r_bayer_mode$q & (~(byte_mask & 64'h3))) | (avs_writedata & (byte_mask & 64'h3))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                4097:
                    begin
                        nx_bayer_black = ((r_bayer_black$q & (~(byte_mask & 64'hfff))) | (avs_writedata & (byte_mask & 64'hfff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                4098:
                    begin
                        nx_bayer_valid = ((r_bayer_valid$q & (~(byte_mask & 64'hfff0fff))) | (avs_writedata & (byte_mask & 64'hfff0fff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                4099:
                    begin
                        nx_bayer_weight_r = ((r_bayer_weight_r$q & (~(byte_mask & 64'hffff))) | (avs_writedata & (byte_mask & 64'hffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                4100:
                    begin
                        nx_bayer_weight_g = ((r_bayer_weight_g$q & (~(byte_mask & 64'hffff))) | (avs_writedata & (byte_mask & 64'hffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                4101:
                    begin
                        nx_bayer_weight_b = ((r_bayer_weight_b$q & (~(byte_mask & 64'hffff))) | (avs_writedata & (byte_mask & 64'hffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                5120:
                    begin
                        nx_dma_ctrl = ((r_dma_ctrl$q & (~(byte_mask & 64'h1))) | (avs_writedata & (byte_mask & 64'h1))) & (~(avs_writedata & (byte_mask & 64'h0)));
                        p_dma_ctrl$d = avs_writedata & (byte_mask & 64'h2);
                    end
                5121:
                    begin
                        nx_dma_window_base = ((r_dma_window_base$q & (~(byte_mask & 64'hffffffff))) | (avs_writedata & (byte_mask & 64'hffffffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                5122:
                    begin
                        nx_dma_window_size = ((r_dma_window_size$q & (~(byte_mask & 64'hffffffff))) | (avs_writedata & (byte_mask & 64'hffffffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                5123:
                    begin
                        nx_dma_slot_stride = ((r_dma_slot_stride$q & (~(byte_mask & 64'hffffffff))) | (avs_writedata & (byte_mask & 64'hffffffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                5124:
                    begin
                        nx_dma_slots = ((r_dma_slots$q & (~(byte_mask & 64'hff))) | (avs_writedata & (byte_mask & 64'hff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                5125:
                    begin
                        nx_dma_status = ((r_dma_status$q & (~(byte_mask & 64'h0))) | (avs_writedata & (byte_mask & 64'h0))) & (~(avs_writedata & (byte_mask & 64'hf0000)));
                    end
                5126:
                    begin
                    end
                5127:
                    begin
                        nx_dma_bus_timeout = ((r_dma_bus_timeout$q & (~(byte_mask & 64'hffffff))) | (avs_writedata & (byte_mask & 64'hffffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                6144:
                    begin
                        p_raybox_ctrl$d = avs_writedata & (byte_mask & 64'h3);
                    end
                6145:
                    begin
                        nx_raybox_work_base = ((r_raybox_work_base$q & (~(byte_mask & 64'hffffffff))) | (avs_writedata & (byte_mask & 64'hffffffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                6146:
                    begin
                        nx_raybox_work_count = ((r_raybox_work_count$q & (~(byte_mask & 64'hffffff))) | (avs_writedata & (byte_mask & 64'hffffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                6147:
                    begin
                        nx_raybox_result_base = ((r_raybox_result_base$q & (~(byte_mask & 64'hffffffff))) | (avs_writedata & (byte_mask & 64'hffffffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                6148:
                    begin
                        nx_raybox_window_base = ((r_raybox_window_base$q & (~(byte_mask & 64'hffffffff))) | (avs_writedata & (byte_mask & 64'hffffffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                6149:
                    begin
                        nx_raybox_window_size = ((r_raybox_window_size$q & (~(byte_mask & 64'hffffffff))) | (avs_writedata & (byte_mask & 64'hffffffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                6150:
                    begin
                        nx_raybox_status = ((r_raybox_status$q & (~(byte_mask & 64'h0))) | (avs_writedata & (byte_mask & 64'h0))) & (~(avs_writedata & (byte_mask & 64'hf0000)));
                    end
                6151:
                    begin
                    end
                6152:
                    begin
                    end
                6153:
                    begin
                        nx_raybox_bus_timeout = ((r_raybox_bus_timeout$q & (~(byte_mask & 64'hffffff))) | (avs_writedata & (byte_mask & 64'hffffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                7168:
                    begin
                        nx_sun_ctrl = ((r_sun_ctrl$q & (~(byte_mask & 64'h71))) | (avs_writedata & (byte_mask & 64'h71))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                7169:
                    begin
                        nx_sun_threshold = ((r_sun_threshold$q & (~(byte_mask & 64'h3fffffff))) | (avs_writedata & (byte_mask & 64'h3fffffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                7170:
                    begin
                        nx_sun_window_x = ((r_sun_window_x$q & (~(byte_mask & 64'h7ff07ff))) | (avs_writedata & (byte_mask & 64'h7ff07ff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                7171:
                    begin
                        nx_sun_window_y = ((r_sun_window_y$q & (~(byte_mask & 64'h7ff07ff))) | (avs_writedata & (byte_mask & 64'h7ff07ff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                7172:
                    begin
                    end
                7173:
                    begin
                    end
                7174:
                    begin
                    end
                7175:
                    begin
                    end
                7176:
                    begin
                    end
                7177:
                    begin
                    end
                7178:
                    begin
                    end
                7179:
                    begin
                    end
                7180:
                    begin
                    end
                7181:
                    begin
                    end
                7182:
                    begin
                    end
                7183:
                    begin
                    end
                8192:
                    begin
                        nx_hdr_ctrl = ((r_hdr_ctrl$q & (~(byte_mask & 64'h1))) | (avs_writedata & (byte_mask & 64'h1))) & (~(avs_writedata & (byte_mask & 64'h0)));
                        p_hdr_ctrl$d = avs_writedata & (byte_mask & 64'h2);
                    end
                8193:
                    begin
                        nx_hdr_min = ((r_hdr_min$q & (~(byte_mask & 64'h7ffffff))) | (avs_writedata & (byte_mask & 64'h7ffffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                8194:
                    begin
                        nx_hdr_max = ((r_hdr_max$q & (~(byte_mask & 64'h7ffffff))) | (avs_writedata & (byte_mask & 64'h7ffffff))) & (~(avs_writedata & (byte_mask & 64'h0)));
                    end
                default:
                    begin
                        unmapped_write = 1'b1;
                        error_word$d = avs_address;
                    end
            endcase
        end
        if (avs_read) begin
            case (avs_address)
                0:
                    begin
                        rdata$d = ((64'h534b594c) & 32'hffffffff);
                    end
                1:
                    begin
                        rdata$d = ((64'h4) & 32'hffffffff);
                    end
                2:
                    begin
                        rdata$d = (r_sys_scratch$q & 64'hffffffff);
                    end
                3:
                    begin
                        rdata$d = (r_sys_bus_status$q & 64'h3);
                    end
                4:
                    begin
                        rdata$d = ((((((error_word$q) & 21'h1fffff) << 32'h2)) & 32'hffffffff));
                    end
                5:
                    begin
                        rdata$d = ((64'h5f5e100) & 32'hffffffff);
                    end
                6:
                    begin
                        rdata$d = (sys_time_lo_cycles);
                    end
                7:
                    begin
                        rdata$d = (sys_time_hi_cycles);
                    end
                8:
                    begin
                        rdata$d = (r_sys_irq_status$q & 64'h3f);
                    end
                9:
                    begin
                        rdata$d = (r_sys_irq_enable$q & 64'h3f);
                    end
                1024:
                    begin
                        rdata$d = (r_i2c_ctrl$q & 64'h2);
                    end
                1025:
                    begin
                        rdata$d = (r_i2c_target$q & 64'h7f);
                    end
                1026:
                    begin
                        rdata$d = (r_i2c_reg_addr$q & 64'hff);
                    end
                1027:
                    begin
                        rdata$d = (r_i2c_write_data$q & 64'hffff);
                    end
                1028:
                    begin
                        rdata$d = (((i2c_read_data_data) & 32'hffffffff));
                    end
                1029:
                    begin
                        rdata$d = (r_i2c_status$q & 64'h3e) | (((i2c_status_busy) & 32'hffffffff));
                    end
                1030:
                    begin
                        rdata$d = (r_i2c_clock_div$q & 64'hffff);
                    end
                1031:
                    begin
                        rdata$d = (r_i2c_timeout$q & 64'hffffff);
                    end
                1032:
                    begin
                        rdata$d = (r_i2c_sensor_pins$q & 64'h1) | (((i2c_sensor_pins_strobe) & 32'hffffffff) << 32'h1);
                    end
                2048:
                    begin
                        rdata$d = (r_seq_ctrl$q & 64'h4);
                    end
                2049:
                    begin
                        rdata$d = (r_seq_count$q & 64'hf);
                    end
                2050:
                    begin
                        rdata$d = (r_seq_status$q & 64'h1f0000) | (((seq_status_busy) & 32'hffffffff)) | (((seq_status_index) & 32'hffffffff) << 32'h4) | (((seq_status_shield_open) & 32'hffffffff) << 32'h8);
                    end
                2051:
                    begin
                        rdata$d = (r_seq_shield_limit$q & 64'hffffffff);
                    end
                2052:
                    begin
                        rdata$d = (r_seq_shield_steps$q & 64'hffff);
                    end
                2053:
                    begin
                        rdata$d = (r_seq_shield_step_period$q & 64'hffffff);
                    end
                2054:
                    begin
                        rdata$d = (seq_frame_number_value);
                    end
                2055:
                    begin
                        rdata$d = (r_seq_trigger_pulse$q & 64'hffff);
                    end
                2064:
                    begin
                        rdata$d = (r_seq_exp_shutter_width_0$q & 64'hfffff);
                    end
                2065:
                    begin
                        rdata$d = (r_seq_exp_shutter_width_1$q & 64'hfffff);
                    end
                2066:
                    begin
                        rdata$d = (r_seq_exp_shutter_width_2$q & 64'hfffff);
                    end
                2067:
                    begin
                        rdata$d = (r_seq_exp_shutter_width_3$q & 64'hfffff);
                    end
                2068:
                    begin
                        rdata$d = (r_seq_exp_shutter_width_4$q & 64'hfffff);
                    end
                2069:
                    begin
                        rdata$d = (r_seq_exp_shutter_width_5$q & 64'hfffff);
                    end
                2070:
                    begin
                        rdata$d = (r_seq_exp_shutter_width_6$q & 64'hfffff);
                    end
                2071:
                    begin
                        rdata$d = (r_seq_exp_shutter_width_7$q & 64'hfffff);
                    end
                2072:
                    begin
                        rdata$d = (r_seq_exp_shutter_delay_0$q & 64'h1fff);
                    end
                2073:
                    begin
                        rdata$d = (r_seq_exp_shutter_delay_1$q & 64'h1fff);
                    end
                2074:
                    begin
                        rdata$d = (r_seq_exp_shutter_delay_2$q & 64'h1fff);
                    end
                2075:
                    begin
                        rdata$d = (r_seq_exp_shutter_delay_3$q & 64'h1fff);
                    end
                2076:
                    begin
                        rdata$d = (r_seq_exp_shutter_delay_4$q & 64'h1fff);
                    end
                2077:
                    begin
                        rdata$d = (r_seq_exp_shutter_delay_5$q & 64'h1fff);
                    end
                2078:
                    begin
                        rdata$d = (r_seq_exp_shutter_delay_6$q & 64'h1fff);
                    end
                2079:
                    begin
                        rdata$d = (r_seq_exp_shutter_delay_7$q & 64'h1fff);
                    end
                2080:
                    begin
                        rdata$d = (r_seq_exp_gain_0$q & 64'hffff);
                    end
                2081:
                    begin
                        rdata$d = (r_seq_exp_gain_1$q & 64'hffff);
                    end
                2082:
                    begin
                        rdata$d = (r_seq_exp_gain_2$q & 64'hffff);
                    end
                2083:
                    begin
                        rdata$d = (r_seq_exp_gain_3$q & 64'hffff);
                    end
                2084:
                    begin
                        rdata$d = (r_seq_exp_gain_4$q & 64'hffff);
                    end
                2085:
                    begin
                        rdata$d = (r_seq_exp_gain_5$q & 64'hffff);
                    end
                2086:
                    begin
                        rdata$d = (r_seq_exp_gain_6$q & 64'hffff);
                    end
                2087:
                    begin
                        rdata$d = (r_seq_exp_gain_7$q & 64'hffff);
                    end
                3072:
                    begin
                        rdata$d = (r_capture_ctrl$q & 64'h3);
                    end
                3073:
                    begin
                        rdata$d = (r_capture_window$q & 64'hfff0fff);
                    end
                3074:
                    begin
                        rdata$d = (r_capture_status$q & 64'h3f00) | (((capture_status_frame_valid) & 32'hffffffff));
                    end
                3075:
                    begin
                        rdata$d = (((capture_last_frame_pixels) & 32'hffffffff)) | (((capture_last_frame_lines) & 32'hffffffff) << 32'h10);
                    end
                3076:
                    begin
                        rdata$d = (((capture_fifo_high_water_words) & 32'hffffffff));
                    end
                3077:
                    begin
                        rdata$d = (capture_frames_count);
                    end
                4096:
                    begin
                        rdata$d = (r_bayer_mode$q & 64'h3);
                    end
                4097:
                    begin
                        rdata$d = (r_bayer_black$q & 64'hfff);
                    end
                4098:
                    begin
                        rdata$d = (r_bayer_valid$q & 64'hfff0fff);
                    end
                4099:
                    begin
                        rdata$d = (r_bayer_weight_r$q & 64'hffff);
                    end
                4100:
                    begin
                        rdata$d = (r_bayer_weight_g$q & 64'hffff);
                    end
                4101:
                    begin
                        rdata$d = (r_bayer_weight_b$q & 64'hffff);
                    end
                5120:
                    begin
                        rdata$d = (r_dma_ctrl$q & 64'h1);
                    end
                5121:
                    begin
                        rdata$d = (r_dma_window_base$q & 64'hffffffff);
                    end
                5122:
                    begin
                        rdata$d = (r_dma_window_size$q & 64'hffffffff);
                    end
                5123:
                    begin
                        rdata$d = (r_dma_slot_stride$q & 64'hffffffff);
                    end
                5124:
                    begin
                        rdata$d = (r_dma_slots$q & 64'hff);
                    end
                5125:
                    begin
                        rdata$d = (r_dma_status$q & 64'hf0000) | (((dma_status_busy) & 32'hffffffff)) | (((dma_status_slot) & 32'hffffffff) << 32'h8);
                    end
                5126:
                    begin
                        rdata$d = (dma_frames_written_count);
                    end
                5127:
                    begin
                        rdata$d = (r_dma_bus_timeout$q & 64'hffffff);
                    end
                6144:
                    begin
                        rdata$d = ((64'h0) & 32'hffffffff);
                    end
                6145:
                    begin
                        rdata$d = (r_raybox_work_base$q & 64'hffffffff);
                    end
                6146:
                    begin
                        rdata$d = (r_raybox_work_count$q & 64'hffffff);
                    end
                6147:
                    begin
                        rdata$d = (r_raybox_result_base$q & 64'hffffffff);
                    end
                6148:
                    begin
                        rdata$d = (r_raybox_window_base$q & 64'hffffffff);
                    end
                6149:
                    begin
                        rdata$d = (r_raybox_window_size$q & 64'hffffffff);
                    end
                6150:
                    begin
                        rdata$d = (r_raybox_status$q & 64'hf0000) | (((raybox_status_busy) & 32'hffffffff));
                    end
                6151:
                    begin
                        rdata$d = (raybox_tests_done_count);
                    end
                6152:
                    begin
                        rdata$d = ((64'h1) & 32'hffffffff) | (((raybox_info_lanes) & 32'hffffffff) << 32'h8);
                    end
                6153:
                    begin
                        rdata$d = (r_raybox_bus_timeout$q & 64'hffffff);
                    end
                7168:
                    begin
                        rdata$d = (r_sun_ctrl$q & 64'h71);
                    end
                7169:
                    begin
                        rdata$d = (r_sun_threshold$q & 64'h3fffffff);
                    end
                7170:
                    begin
                        rdata$d = (r_sun_window_x$q & 64'h7ff07ff);
                    end
                7171:
                    begin
                        rdata$d = (r_sun_window_y$q & 64'h7ff07ff);
                    end
                7172:
                    begin
                        rdata$d = (((sun_count_groups) & 32'hffffffff));
                    end
                7173:
                    begin
                        rdata$d = (((sun_over_count_groups) & 32'hffffffff));
                    end
                7174:
                    begin
                        rdata$d = (sun_sum_l_lo_value);
                    end
                7175:
                    begin
                        rdata$d = (sun_sum_l_hi_value);
                    end
                7176:
                    begin
                        rdata$d = (sun_sum_xl_lo_value);
                    end
                7177:
                    begin
                        rdata$d = (sun_sum_xl_hi_value);
                    end
                7178:
                    begin
                        rdata$d = (sun_sum_yl_lo_value);
                    end
                7179:
                    begin
                        rdata$d = (sun_sum_yl_hi_value);
                    end
                7180:
                    begin
                        rdata$d = (((sun_max_l_q14) & 32'hffffffff));
                    end
                7181:
                    begin
                        rdata$d = (((sun_box_x_min) & 32'hffffffff)) | (((sun_box_x_max) & 32'hffffffff) << 32'h10);
                    end
                7182:
                    begin
                        rdata$d = (((sun_box_y_min) & 32'hffffffff)) | (((sun_box_y_max) & 32'hffffffff) << 32'h10);
                    end
                7183:
                    begin
                        rdata$d = (((sun_frames_count) & 32'hffffffff));
                    end
                8192:
                    begin
                        rdata$d = (r_hdr_ctrl$q & 64'h1);
                    end
                8193:
                    begin
                        rdata$d = (r_hdr_min$q & 64'h7ffffff);
                    end
                8194:
                    begin
                        rdata$d = (r_hdr_max$q & 64'h7ffffff);
                    end
                default:
                    begin
                        rdata$d = ((64'hdeadbeef) & 32'hffffffff);
                        unmapped_read = 1'b1;
                        error_word$d = avs_address;
                    end
            endcase
        end
        r_sys_scratch$d = nx_sys_scratch;
        sys_scratch_value = r_sys_scratch$q;
        r_sys_bus_status$d = ((nx_sys_bus_status | (((unmapped_read) & 32'hffffffff))) | (((unmapped_write) & 32'hffffffff) << 32'h1));
        sys_bus_status_unmapped_read = r_sys_bus_status$q[32'h0];
        sys_bus_status_unmapped_write = r_sys_bus_status$q[32'h1];
        r_sys_irq_status$d = ((((((nx_sys_irq_status | (((sys_irq_status_frame_done_set) & 32'hffffffff))) | (((sys_irq_status_sequence_done_set) & 32'hffffffff) << 32'h1)) | (((sys_irq_status_dma_error_set) & 32'hffffffff) << 32'h2)) | (((sys_irq_status_capture_error_set) & 32'hffffffff) << 32'h3)) | (((sys_irq_status_i2c_done_set) & 32'hffffffff) << 32'h4)) | (((sys_irq_status_raybox_done_set) & 32'hffffffff) << 32'h5));
        sys_irq_status_frame_done = r_sys_irq_status$q[32'h0];
        sys_irq_status_sequence_done = r_sys_irq_status$q[32'h1];
        sys_irq_status_dma_error = r_sys_irq_status$q[32'h2];
        sys_irq_status_capture_error = r_sys_irq_status$q[32'h3];
        sys_irq_status_i2c_done = r_sys_irq_status$q[32'h4];
        sys_irq_status_raybox_done = r_sys_irq_status$q[32'h5];
        r_sys_irq_enable$d = nx_sys_irq_enable;
        sys_irq_enable_frame_done = r_sys_irq_enable$q[32'h0];
        sys_irq_enable_sequence_done = r_sys_irq_enable$q[32'h1];
        sys_irq_enable_dma_error = r_sys_irq_enable$q[32'h2];
        sys_irq_enable_capture_error = r_sys_irq_enable$q[32'h3];
        sys_irq_enable_i2c_done = r_sys_irq_enable$q[32'h4];
        sys_irq_enable_raybox_done = r_sys_irq_enable$q[32'h5];
        r_i2c_ctrl$d = nx_i2c_ctrl;
        i2c_ctrl_start = p_i2c_ctrl$q[32'h0];
        i2c_ctrl_read = r_i2c_ctrl$q[32'h1];
        r_i2c_target$d = nx_i2c_target;
        i2c_target_addr7 = r_i2c_target$q[(32'h0)+:(7)];
        r_i2c_reg_addr$d = nx_i2c_reg_addr;
        i2c_reg_addr_addr = r_i2c_reg_addr$q[(32'h0)+:(8)];
        r_i2c_write_data$d = nx_i2c_write_data;
        i2c_write_data_data = r_i2c_write_data$q[(32'h0)+:(16)];
        r_i2c_status$d = (((((nx_i2c_status | (((i2c_status_done_set) & 32'hffffffff) << 32'h1)) | (((i2c_status_nack_set) & 32'hffffffff) << 32'h2)) | (((i2c_status_timeout_set) & 32'hffffffff) << 32'h3)) | (((i2c_status_bus_stuck_set) & 32'hffffffff) << 32'h4)) | (((i2c_status_refused_set) & 32'hffffffff) << 32'h5));
        i2c_status_done = r_i2c_status$q[32'h1];
        i2c_status_nack = r_i2c_status$q[32'h2];
        i2c_status_timeout = r_i2c_status$q[32'h3];
        i2c_status_bus_stuck = r_i2c_status$q[32'h4];
        i2c_status_refused = r_i2c_status$q[32'h5];
        r_i2c_clock_div$d = nx_i2c_clock_div;
        i2c_clock_div_half_period = r_i2c_clock_div$q[(32'h0)+:(16)];
        r_i2c_timeout$d = nx_i2c_timeout;
        i2c_timeout_cycles = r_i2c_timeout$q[(32'h0)+:(24)];
        r_i2c_sensor_pins$d = nx_i2c_sensor_pins;
        i2c_sensor_pins_reset_n = r_i2c_sensor_pins$q[32'h0];
        r_seq_ctrl$d = nx_seq_ctrl;
        seq_ctrl_start = p_seq_ctrl$q[32'h0];
        seq_ctrl_abort = p_seq_ctrl$q[32'h1];
        seq_ctrl_ext_trigger = r_seq_ctrl$q[32'h2];
        r_seq_count$d = nx_seq_count;
        seq_count_exposures = r_seq_count$q[(32'h0)+:(4)];
        r_seq_status$d = (((((nx_seq_status | (((seq_status_done_set) & 32'hffffffff) << 32'h10)) | (((seq_status_shield_limit_hit_set) & 32'hffffffff) << 32'h11)) | (((seq_status_i2c_error_set) & 32'hffffffff) << 32'h12)) | (((seq_status_refused_set) & 32'hffffffff) << 32'h13)) | (((seq_status_aborted_set) & 32'hffffffff) << 32'h14));
        seq_status_done = r_seq_status$q[32'h10];
        seq_status_shield_limit_hit = r_seq_status$q[32'h11];
        seq_status_i2c_error = r_seq_status$q[32'h12];
        seq_status_refused = r_seq_status$q[32'h13];
        seq_status_aborted = r_seq_status$q[32'h14];
        r_seq_shield_limit$d = nx_seq_shield_limit;
        seq_shield_limit_cycles = r_seq_shield_limit$q;
        r_seq_shield_steps$d = nx_seq_shield_steps;
        seq_shield_steps_steps = r_seq_shield_steps$q[(32'h0)+:(16)];
        r_seq_shield_step_period$d = nx_seq_shield_step_period;
        seq_shield_step_period_cycles = r_seq_shield_step_period$q[(32'h0)+:(24)];
        r_seq_trigger_pulse$d = nx_seq_trigger_pulse;
        seq_trigger_pulse_cycles = r_seq_trigger_pulse$q[(32'h0)+:(16)];
        r_seq_exp_shutter_width_0$d = nx_seq_exp_shutter_width_0;
        seq_exp_shutter_width_rows$0 = r_seq_exp_shutter_width_0$q[(32'h0)+:(20)];
        r_seq_exp_shutter_width_1$d = nx_seq_exp_shutter_width_1;
        seq_exp_shutter_width_rows$1 = r_seq_exp_shutter_width_1$q[(32'h0)+:(20)];
        r_seq_exp_shutter_width_2$d = nx_seq_exp_shutter_width_2;
        seq_exp_shutter_width_rows$2 = r_seq_exp_shutter_width_2$q[(32'h0)+:(20)];
        r_seq_exp_shutter_width_3$d = nx_seq_exp_shutter_width_3;
        seq_exp_shutter_width_rows$3 = r_seq_exp_shutter_width_3$q[(32'h0)+:(20)];
        r_seq_exp_shutter_width_4$d = nx_seq_exp_shutter_width_4;
        seq_exp_shutter_width_rows$4 = r_seq_exp_shutter_width_4$q[(32'h0)+:(20)];
        r_seq_exp_shutter_width_5$d = nx_seq_exp_shutter_width_5;
        seq_exp_shutter_width_rows$5 = r_seq_exp_shutter_width_5$q[(32'h0)+:(20)];
        r_seq_exp_shutter_width_6$d = nx_seq_exp_shutter_width_6;
        seq_exp_shutter_width_rows$6 = r_seq_exp_shutter_width_6$q[(32'h0)+:(20)];
        r_seq_exp_shutter_width_7$d = nx_seq_exp_shutter_width_7;
        seq_exp_shutter_width_rows$7 = r_seq_exp_shutter_width_7$q[(32'h0)+:(20)];
        r_seq_exp_shutter_delay_0$d = nx_seq_exp_shutter_delay_0;
        seq_exp_shutter_delay_value$0 = r_seq_exp_shutter_delay_0$q[(32'h0)+:(13)];
        r_seq_exp_shutter_delay_1$d = nx_seq_exp_shutter_delay_1;
        seq_exp_shutter_delay_value$1 = r_seq_exp_shutter_delay_1$q[(32'h0)+:(13)];
        r_seq_exp_shutter_delay_2$d = nx_seq_exp_shutter_delay_2;
        seq_exp_shutter_delay_value$2 = r_seq_exp_shutter_delay_2$q[(32'h0)+:(13)];
        r_seq_exp_shutter_delay_3$d = nx_seq_exp_shutter_delay_3;
        seq_exp_shutter_delay_value$3 = r_seq_exp_shutter_delay_3$q[(32'h0)+:(13)];
        r_seq_exp_shutter_delay_4$d = nx_seq_exp_shutter_delay_4;
        seq_exp_shutter_delay_value$4 = r_seq_exp_shutter_delay_4$q[(32'h0)+:(13)];
        r_seq_exp_shutter_delay_5$d = nx_seq_exp_shutter_delay_5;
        seq_exp_shutter_delay_value$5 = r_seq_exp_shutter_delay_5$q[(32'h0)+:(13)];
        r_seq_exp_shutter_delay_6$d = nx_seq_exp_shutter_delay_6;
        seq_exp_shutter_delay_value$6 = r_seq_exp_shutter_delay_6$q[(32'h0)+:(13)];
        r_seq_exp_shutter_delay_7$d = nx_seq_exp_shutter_delay_7;
        seq_exp_shutter_delay_value$7 = r_seq_exp_shutter_delay_7$q[(32'h0)+:(13)];
        r_seq_exp_gain_0$d = nx_seq_exp_gain_0;
        seq_exp_gain_code$0 = r_seq_exp_gain_0$q[(32'h0)+:(16)];
        r_seq_exp_gain_1$d = nx_seq_exp_gain_1;
        seq_exp_gain_code$1 = r_seq_exp_gain_1$q[(32'h0)+:(16)];
        r_seq_exp_gain_2$d = nx_seq_exp_gain_2;
        seq_exp_gain_code$2 = r_seq_exp_gain_2$q[(32'h0)+:(16)];
        r_seq_exp_gain_3$d = nx_seq_exp_gain_3;
        seq_exp_gain_code$3 = r_seq_exp_gain_3$q[(32'h0)+:(16)];
        r_seq_exp_gain_4$d = nx_seq_exp_gain_4;
        seq_exp_gain_code$4 = r_seq_exp_gain_4$q[(32'h0)+:(16)];
        r_seq_exp_gain_5$d = nx_seq_exp_gain_5;
        seq_exp_gain_code$5 = r_seq_exp_gain_5$q[(32'h0)+:(16)];
        r_seq_exp_gain_6$d = nx_seq_exp_gain_6;
        seq_exp_gain_code$6 = r_seq_exp_gain_6$q[(32'h0)+:(16)];
        r_seq_exp_gain_7$d = nx_seq_exp_gain_7;
        seq_exp_gain_code$7 = r_seq_exp_gain_7$q[(32'h0)+:(16)];
        r_capture_ctrl$d = nx_capture_ctrl;
        capture_ctrl_enable = r_capture_ctrl$q[32'h0];
        capture_ctrl_raw = r_capture_ctrl$q[32'h1];
        r_capture_window$d = nx_capture_window;
        capture_window_width = r_capture_window$q[(32'h0)+:(12)];
        capture_window_height = r_capture_window$q[(32'h10)+:(12)];
        r_capture_status$d = ((((((nx_capture_status | (((capture_status_line_short_set) & 32'hffffffff) << 32'h8)) | (((capture_status_line_long_set) & 32'hffffffff) << 32'h9)) | (((capture_status_frame_short_set) & 32'hffffffff) << 32'ha)) | (((capture_status_frame_long_set) & 32'hffffffff) << 32'hb)) | (((capture_status_fifo_overflow_set) & 32'hffffffff) << 32'hc)) | (((capture_status_pixclk_stopped_set) & 32'hffffffff) << 32'hd));
        capture_status_line_short = r_capture_status$q[32'h8];
        capture_status_line_long = r_capture_status$q[32'h9];
        capture_status_frame_short = r_capture_status$q[32'ha];
        capture_status_frame_long = r_capture_status$q[32'hb];
        capture_status_fifo_overflow = r_capture_status$q[32'hc];
        capture_status_pixclk_stopped = r_capture_status$q[32'hd];
        r_bayer_mode$d = nx_bayer_mode;
        bayer_mode_phase = r_bayer_mode$q[(32'h0)+:(2)];
        r_bayer_black$d = nx_bayer_black;
        bayer_black_level = r_bayer_black$q[(32'h0)+:(12)];
        r_bayer_valid$d = nx_bayer_valid;
        bayer_valid_min = r_bayer_valid$q[(32'h0)+:(12)];
        bayer_valid_max = r_bayer_valid$q[(32'h10)+:(12)];
        r_bayer_weight_r$d = nx_bayer_weight_r;
        bayer_weight_r_q2_14 = r_bayer_weight_r$q[(32'h0)+:(16)];
        r_bayer_weight_g$d = nx_bayer_weight_g;
        bayer_weight_g_q2_14 = r_bayer_weight_g$q[(32'h0)+:(16)];
        r_bayer_weight_b$d = nx_bayer_weight_b;
        bayer_weight_b_q2_14 = r_bayer_weight_b$q[(32'h0)+:(16)];
        r_dma_ctrl$d = nx_dma_ctrl;
        dma_ctrl_enable = r_dma_ctrl$q[32'h0];
        dma_ctrl_reset = p_dma_ctrl$q[32'h1];
        r_dma_window_base$d = nx_dma_window_base;
        dma_window_base_addr = r_dma_window_base$q;
        r_dma_window_size$d = nx_dma_window_size;
        dma_window_size_bytes = r_dma_window_size$q;
        r_dma_slot_stride$d = nx_dma_slot_stride;
        dma_slot_stride_bytes = r_dma_slot_stride$q;
        r_dma_slots$d = nx_dma_slots;
        dma_slots_count = r_dma_slots$q[(32'h0)+:(8)];
        r_dma_status$d = ((((nx_dma_status | (((dma_status_frame_done_set) & 32'hffffffff) << 32'h10)) | (((dma_status_out_of_window_set) & 32'hffffffff) << 32'h11)) | (((dma_status_overflow_set) & 32'hffffffff) << 32'h12)) | (((dma_status_bus_timeout_set) & 32'hffffffff) << 32'h13));
        dma_status_frame_done = r_dma_status$q[32'h10];
        dma_status_out_of_window = r_dma_status$q[32'h11];
        dma_status_overflow = r_dma_status$q[32'h12];
        dma_status_bus_timeout = r_dma_status$q[32'h13];
        r_dma_bus_timeout$d = nx_dma_bus_timeout;
        dma_bus_timeout_cycles = r_dma_bus_timeout$q[(32'h0)+:(24)];
        raybox_ctrl_start = p_raybox_ctrl$q[32'h0];
        raybox_ctrl_abort = p_raybox_ctrl$q[32'h1];
        r_raybox_work_base$d = nx_raybox_work_base;
        raybox_work_base_addr = r_raybox_work_base$q;
        r_raybox_work_count$d = nx_raybox_work_count;
        raybox_work_count_items = r_raybox_work_count$q[(32'h0)+:(24)];
        r_raybox_result_base$d = nx_raybox_result_base;
        raybox_result_base_addr = r_raybox_result_base$q;
        r_raybox_window_base$d = nx_raybox_window_base;
        raybox_window_base_addr = r_raybox_window_base$q;
        r_raybox_window_size$d = nx_raybox_window_size;
        raybox_window_size_bytes = r_raybox_window_size$q;
        r_raybox_status$d = ((((nx_raybox_status | (((raybox_status_done_set) & 32'hffffffff) << 32'h10)) | (((raybox_status_bad_descriptor_set) & 32'hffffffff) << 32'h11)) | (((raybox_status_out_of_window_set) & 32'hffffffff) << 32'h12)) | (((raybox_status_bus_timeout_set) & 32'hffffffff) << 32'h13));
        raybox_status_done = r_raybox_status$q[32'h10];
        raybox_status_bad_descriptor = r_raybox_status$q[32'h11];
        raybox_status_out_of_window = r_raybox_status$q[32'h12];
        raybox_status_bus_timeout = r_raybox_status$q[32'h13];
        r_raybox_bus_timeout$d = nx_raybox_bus_timeout;
        raybox_bus_timeout_cycles = r_raybox_bus_timeout$q[(32'h0)+:(24)];
        r_sun_ctrl$d = nx_sun_ctrl;
        sun_ctrl_enable = r_sun_ctrl$q[32'h0];
        sun_ctrl_exposure_index = r_sun_ctrl$q[(32'h4)+:(3)];
        r_sun_threshold$d = nx_sun_threshold;
        sun_threshold_q14 = r_sun_threshold$q[(32'h0)+:(30)];
        r_sun_window_x$d = nx_sun_window_x;
        sun_window_x_min = r_sun_window_x$q[(32'h0)+:(11)];
        sun_window_x_max = r_sun_window_x$q[(32'h10)+:(11)];
        r_sun_window_y$d = nx_sun_window_y;
        sun_window_y_min = r_sun_window_y$q[(32'h0)+:(11)];
        sun_window_y_max = r_sun_window_y$q[(32'h10)+:(11)];
        r_hdr_ctrl$d = nx_hdr_ctrl;
        hdr_ctrl_enable = r_hdr_ctrl$q[32'h0];
        hdr_ctrl_new_set = p_hdr_ctrl$q[32'h1];
        r_hdr_min$d = nx_hdr_min;
        hdr_min_q11 = r_hdr_min$q[(32'h0)+:(27)];
        r_hdr_max$d = nx_hdr_max;
        hdr_max_q11 = r_hdr_max$q[(32'h0)+:(27)];
        avs_readdata = rdata$q;
        irq = |(r_sys_irq_status$q & r_sys_irq_enable$q);
    end
    
endmodule // skylux_core$regs


module skylux_core$regs$error_word(d,q,clock);
    
    // Module arguments
    input wire  [18:0] d;
    output reg  [18:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 19'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$error_word


module skylux_core$regs$p_dma_ctrl(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$p_dma_ctrl


module skylux_core$regs$p_hdr_ctrl(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$p_hdr_ctrl


module skylux_core$regs$p_i2c_ctrl(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$p_i2c_ctrl


module skylux_core$regs$p_raybox_ctrl(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$p_raybox_ctrl


module skylux_core$regs$p_seq_ctrl(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$p_seq_ctrl


module skylux_core$regs$r_bayer_black(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_bayer_black$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_bayer_black


module skylux_core$regs$r_bayer_black$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_bayer_black$dff


module skylux_core$regs$r_bayer_mode(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_bayer_mode$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_bayer_mode


module skylux_core$regs$r_bayer_mode$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_bayer_mode$dff


module skylux_core$regs$r_bayer_valid(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'hfff0000;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_bayer_valid$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_bayer_valid


module skylux_core$regs$r_bayer_valid$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_bayer_valid$dff


module skylux_core$regs$r_bayer_weight_b(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h1000;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_bayer_weight_b$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_bayer_weight_b


module skylux_core$regs$r_bayer_weight_b$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_bayer_weight_b$dff


module skylux_core$regs$r_bayer_weight_g(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h2000;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_bayer_weight_g$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_bayer_weight_g


module skylux_core$regs$r_bayer_weight_g$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_bayer_weight_g$dff


module skylux_core$regs$r_bayer_weight_r(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h1000;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_bayer_weight_r$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_bayer_weight_r


module skylux_core$regs$r_bayer_weight_r$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_bayer_weight_r$dff


module skylux_core$regs$r_capture_ctrl(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_capture_ctrl$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_capture_ctrl


module skylux_core$regs$r_capture_ctrl$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_capture_ctrl$dff


module skylux_core$regs$r_capture_status(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_capture_status$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_capture_status


module skylux_core$regs$r_capture_status$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_capture_status$dff


module skylux_core$regs$r_capture_window(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h7980a20;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_capture_window$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_capture_window


module skylux_core$regs$r_capture_window$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_capture_window$dff


module skylux_core$regs$r_dma_bus_timeout(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'hf4240;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_dma_bus_timeout$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_dma_bus_timeout


module skylux_core$regs$r_dma_bus_timeout$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_dma_bus_timeout$dff


module skylux_core$regs$r_dma_ctrl(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_dma_ctrl$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_dma_ctrl


module skylux_core$regs$r_dma_ctrl$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_dma_ctrl$dff


module skylux_core$regs$r_dma_slot_stride(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_dma_slot_stride$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_dma_slot_stride


module skylux_core$regs$r_dma_slot_stride$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_dma_slot_stride$dff


module skylux_core$regs$r_dma_slots(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h4;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_dma_slots$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_dma_slots


module skylux_core$regs$r_dma_slots$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_dma_slots$dff


module skylux_core$regs$r_dma_status(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_dma_status$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_dma_status


module skylux_core$regs$r_dma_status$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_dma_status$dff


module skylux_core$regs$r_dma_window_base(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_dma_window_base$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_dma_window_base


module skylux_core$regs$r_dma_window_base$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_dma_window_base$dff


module skylux_core$regs$r_dma_window_size(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_dma_window_size$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_dma_window_size


module skylux_core$regs$r_dma_window_size$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_dma_window_size$dff


module skylux_core$regs$r_hdr_ctrl(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_hdr_ctrl$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_hdr_ctrl


module skylux_core$regs$r_hdr_ctrl$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_hdr_ctrl$dff


module skylux_core$regs$r_hdr_max(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h7ffffff;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_hdr_max$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_hdr_max


module skylux_core$regs$r_hdr_max$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_hdr_max$dff


module skylux_core$regs$r_hdr_min(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_hdr_min$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_hdr_min


module skylux_core$regs$r_hdr_min$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_hdr_min$dff


module skylux_core$regs$r_i2c_clock_div(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h1f4;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_i2c_clock_div$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_i2c_clock_div


module skylux_core$regs$r_i2c_clock_div$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_i2c_clock_div$dff


module skylux_core$regs$r_i2c_ctrl(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_i2c_ctrl$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_i2c_ctrl


module skylux_core$regs$r_i2c_ctrl$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_i2c_ctrl$dff


module skylux_core$regs$r_i2c_reg_addr(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_i2c_reg_addr$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_i2c_reg_addr


module skylux_core$regs$r_i2c_reg_addr$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_i2c_reg_addr$dff


module skylux_core$regs$r_i2c_sensor_pins(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_i2c_sensor_pins$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_i2c_sensor_pins


module skylux_core$regs$r_i2c_sensor_pins$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_i2c_sensor_pins$dff


module skylux_core$regs$r_i2c_status(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_i2c_status$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_i2c_status


module skylux_core$regs$r_i2c_status$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_i2c_status$dff


module skylux_core$regs$r_i2c_target(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h5d;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_i2c_target$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_i2c_target


module skylux_core$regs$r_i2c_target$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_i2c_target$dff


module skylux_core$regs$r_i2c_timeout(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'hf4240;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_i2c_timeout$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_i2c_timeout


module skylux_core$regs$r_i2c_timeout$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_i2c_timeout$dff


module skylux_core$regs$r_i2c_write_data(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_i2c_write_data$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_i2c_write_data


module skylux_core$regs$r_i2c_write_data$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_i2c_write_data$dff


module skylux_core$regs$r_raybox_bus_timeout(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'hf4240;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_raybox_bus_timeout$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_raybox_bus_timeout


module skylux_core$regs$r_raybox_bus_timeout$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_raybox_bus_timeout$dff


module skylux_core$regs$r_raybox_result_base(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_raybox_result_base$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_raybox_result_base


module skylux_core$regs$r_raybox_result_base$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_raybox_result_base$dff


module skylux_core$regs$r_raybox_status(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_raybox_status$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_raybox_status


module skylux_core$regs$r_raybox_status$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_raybox_status$dff


module skylux_core$regs$r_raybox_window_base(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_raybox_window_base$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_raybox_window_base


module skylux_core$regs$r_raybox_window_base$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_raybox_window_base$dff


module skylux_core$regs$r_raybox_window_size(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_raybox_window_size$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_raybox_window_size


module skylux_core$regs$r_raybox_window_size$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_raybox_window_size$dff


module skylux_core$regs$r_raybox_work_base(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_raybox_work_base$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_raybox_work_base


module skylux_core$regs$r_raybox_work_base$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_raybox_work_base$dff


module skylux_core$regs$r_raybox_work_count(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_raybox_work_count$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_raybox_work_count


module skylux_core$regs$r_raybox_work_count$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_raybox_work_count$dff


module skylux_core$regs$r_seq_count(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h5;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_seq_count$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_seq_count


module skylux_core$regs$r_seq_count$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_seq_count$dff


module skylux_core$regs$r_seq_ctrl(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_seq_ctrl$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_seq_ctrl


module skylux_core$regs$r_seq_ctrl$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_seq_ctrl$dff


module skylux_core$regs$r_seq_exp_gain_0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h8;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_seq_exp_gain_0$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_seq_exp_gain_0


module skylux_core$regs$r_seq_exp_gain_0$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_seq_exp_gain_0$dff


module skylux_core$regs$r_seq_exp_gain_1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h8;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_seq_exp_gain_1$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_seq_exp_gain_1


module skylux_core$regs$r_seq_exp_gain_1$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_seq_exp_gain_1$dff


module skylux_core$regs$r_seq_exp_gain_2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h8;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_seq_exp_gain_2$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_seq_exp_gain_2


module skylux_core$regs$r_seq_exp_gain_2$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_seq_exp_gain_2$dff


module skylux_core$regs$r_seq_exp_gain_3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h8;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_seq_exp_gain_3$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_seq_exp_gain_3


module skylux_core$regs$r_seq_exp_gain_3$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_seq_exp_gain_3$dff


module skylux_core$regs$r_seq_exp_gain_4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h8;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_seq_exp_gain_4$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_seq_exp_gain_4


module skylux_core$regs$r_seq_exp_gain_4$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_seq_exp_gain_4$dff


module skylux_core$regs$r_seq_exp_gain_5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h8;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_seq_exp_gain_5$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_seq_exp_gain_5


module skylux_core$regs$r_seq_exp_gain_5$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_seq_exp_gain_5$dff


module skylux_core$regs$r_seq_exp_gain_6(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h8;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_seq_exp_gain_6$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_seq_exp_gain_6


module skylux_core$regs$r_seq_exp_gain_6$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_seq_exp_gain_6$dff


module skylux_core$regs$r_seq_exp_gain_7(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h8;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_seq_exp_gain_7$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_seq_exp_gain_7


module skylux_core$regs$r_seq_exp_gain_7$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_seq_exp_gain_7$dff


module skylux_core$regs$r_seq_exp_shutter_delay_0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_seq_exp_shutter_delay_0$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_seq_exp_shutter_delay_0


module skylux_core$regs$r_seq_exp_shutter_delay_0$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_seq_exp_shutter_delay_0$dff


module skylux_core$regs$r_seq_exp_shutter_delay_1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_seq_exp_shutter_delay_1$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_seq_exp_shutter_delay_1


module skylux_core$regs$r_seq_exp_shutter_delay_1$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_seq_exp_shutter_delay_1$dff


module skylux_core$regs$r_seq_exp_shutter_delay_2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_seq_exp_shutter_delay_2$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_seq_exp_shutter_delay_2


module skylux_core$regs$r_seq_exp_shutter_delay_2$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_seq_exp_shutter_delay_2$dff


module skylux_core$regs$r_seq_exp_shutter_delay_3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_seq_exp_shutter_delay_3$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_seq_exp_shutter_delay_3


module skylux_core$regs$r_seq_exp_shutter_delay_3$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_seq_exp_shutter_delay_3$dff


module skylux_core$regs$r_seq_exp_shutter_delay_4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_seq_exp_shutter_delay_4$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_seq_exp_shutter_delay_4


module skylux_core$regs$r_seq_exp_shutter_delay_4$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_seq_exp_shutter_delay_4$dff


module skylux_core$regs$r_seq_exp_shutter_delay_5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_seq_exp_shutter_delay_5$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_seq_exp_shutter_delay_5


module skylux_core$regs$r_seq_exp_shutter_delay_5$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_seq_exp_shutter_delay_5$dff


module skylux_core$regs$r_seq_exp_shutter_delay_6(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_seq_exp_shutter_delay_6$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_seq_exp_shutter_delay_6


module skylux_core$regs$r_seq_exp_shutter_delay_6$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_seq_exp_shutter_delay_6$dff


module skylux_core$regs$r_seq_exp_shutter_delay_7(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_seq_exp_shutter_delay_7$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_seq_exp_shutter_delay_7


module skylux_core$regs$r_seq_exp_shutter_delay_7$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_seq_exp_shutter_delay_7$dff


module skylux_core$regs$r_seq_exp_shutter_width_0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h1;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_seq_exp_shutter_width_0$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_seq_exp_shutter_width_0


module skylux_core$regs$r_seq_exp_shutter_width_0$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_seq_exp_shutter_width_0$dff


module skylux_core$regs$r_seq_exp_shutter_width_1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h1;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_seq_exp_shutter_width_1$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_seq_exp_shutter_width_1


module skylux_core$regs$r_seq_exp_shutter_width_1$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_seq_exp_shutter_width_1$dff


module skylux_core$regs$r_seq_exp_shutter_width_2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h1;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_seq_exp_shutter_width_2$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_seq_exp_shutter_width_2


module skylux_core$regs$r_seq_exp_shutter_width_2$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_seq_exp_shutter_width_2$dff


module skylux_core$regs$r_seq_exp_shutter_width_3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h1;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_seq_exp_shutter_width_3$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_seq_exp_shutter_width_3


module skylux_core$regs$r_seq_exp_shutter_width_3$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_seq_exp_shutter_width_3$dff


module skylux_core$regs$r_seq_exp_shutter_width_4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h1;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_seq_exp_shutter_width_4$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_seq_exp_shutter_width_4


module skylux_core$regs$r_seq_exp_shutter_width_4$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_seq_exp_shutter_width_4$dff


module skylux_core$regs$r_seq_exp_shutter_width_5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h1;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_seq_exp_shutter_width_5$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_seq_exp_shutter_width_5


module skylux_core$regs$r_seq_exp_shutter_width_5$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_seq_exp_shutter_width_5$dff


module skylux_core$regs$r_seq_exp_shutter_width_6(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h1;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_seq_exp_shutter_width_6$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_seq_exp_shutter_width_6


module skylux_core$regs$r_seq_exp_shutter_width_6$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_seq_exp_shutter_width_6$dff


module skylux_core$regs$r_seq_exp_shutter_width_7(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h1;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_seq_exp_shutter_width_7$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_seq_exp_shutter_width_7


module skylux_core$regs$r_seq_exp_shutter_width_7$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_seq_exp_shutter_width_7$dff


module skylux_core$regs$r_seq_shield_limit(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h3473bc0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_seq_shield_limit$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_seq_shield_limit


module skylux_core$regs$r_seq_shield_limit$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_seq_shield_limit$dff


module skylux_core$regs$r_seq_shield_step_period(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'hc350;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_seq_shield_step_period$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_seq_shield_step_period


module skylux_core$regs$r_seq_shield_step_period$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_seq_shield_step_period$dff


module skylux_core$regs$r_seq_shield_steps(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'hc8;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_seq_shield_steps$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_seq_shield_steps


module skylux_core$regs$r_seq_shield_steps$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_seq_shield_steps$dff


module skylux_core$regs$r_seq_status(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_seq_status$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_seq_status


module skylux_core$regs$r_seq_status$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_seq_status$dff


module skylux_core$regs$r_seq_trigger_pulse(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h64;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_seq_trigger_pulse$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_seq_trigger_pulse


module skylux_core$regs$r_seq_trigger_pulse$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_seq_trigger_pulse$dff


module skylux_core$regs$r_sun_ctrl(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_sun_ctrl$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_sun_ctrl


module skylux_core$regs$r_sun_ctrl$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_sun_ctrl$dff


module skylux_core$regs$r_sun_threshold(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h3fffffff;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_sun_threshold$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_sun_threshold


module skylux_core$regs$r_sun_threshold$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_sun_threshold$dff


module skylux_core$regs$r_sun_window_x(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h7ff0000;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_sun_window_x$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_sun_window_x


module skylux_core$regs$r_sun_window_x$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_sun_window_x$dff


module skylux_core$regs$r_sun_window_y(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h7ff0000;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_sun_window_y$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_sun_window_y


module skylux_core$regs$r_sun_window_y$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_sun_window_y$dff


module skylux_core$regs$r_sys_bus_status(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_sys_bus_status$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_sys_bus_status


module skylux_core$regs$r_sys_bus_status$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_sys_bus_status$dff


module skylux_core$regs$r_sys_irq_enable(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_sys_irq_enable$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_sys_irq_enable


module skylux_core$regs$r_sys_irq_enable$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_sys_irq_enable$dff


module skylux_core$regs$r_sys_irq_status(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_sys_irq_status$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_sys_irq_status


module skylux_core$regs$r_sys_irq_status$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_sys_irq_status$dff


module skylux_core$regs$r_sys_scratch(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 32'h0;
    
    // Stub signals
    reg  [31:0] dff$d;
    wire  [31:0] dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$regs$r_sys_scratch$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$regs$r_sys_scratch


module skylux_core$regs$r_sys_scratch$dff(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$r_sys_scratch$dff


module skylux_core$regs$rdata(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$regs$rdata


module skylux_core$sensor(clock,i2c_ctrl_start,i2c_ctrl_read,i2c_target_addr7,i2c_reg_addr_addr,i2c_write_data_data,i2c_clock_div_half_period,i2c_timeout_cycles,i2c_read_data_data,i2c_status_busy,i2c_status_done_set,i2c_status_nack_set,i2c_status_timeout_set,i2c_status_bus_stuck_set,i2c_status_refused_set,seq_ctrl_start,seq_ctrl_abort,seq_ctrl_ext_trigger,seq_count_exposures,seq_shield_limit_cycles,seq_shield_steps_steps,seq_shield_step_period_cycles,seq_trigger_pulse_cycles,seq_exp_shutter_width_rows$0,seq_exp_shutter_width_rows$1,seq_exp_shutter_width_rows$2,seq_exp_shutter_width_rows$3,seq_exp_shutter_width_rows$4,seq_exp_shutter_width_rows$5,seq_exp_shutter_width_rows$6,seq_exp_shutter_width_rows$7,seq_exp_shutter_delay_value$0,seq_exp_shutter_delay_value$1,seq_exp_shutter_delay_value$2,seq_exp_shutter_delay_value$3,seq_exp_shutter_delay_value$4,seq_exp_shutter_delay_value$5,seq_exp_shutter_delay_value$6,seq_exp_shutter_delay_value$7,seq_exp_gain_code$0,seq_exp_gain_code$1,seq_exp_gain_code$2,seq_exp_gain_code$3,seq_exp_gain_code$4,seq_exp_gain_code$5,seq_exp_gain_code$6,seq_exp_gain_code$7,seq_status_busy,seq_status_index,seq_status_shield_open,seq_status_done_set,seq_status_shield_limit_hit_set,seq_status_i2c_error_set,seq_status_refused_set,seq_status_aborted_set,seq_frame_number_value,time_cycles,ext_trigger,frame_valid,scl_in,sda_in,scl_low,sda_low,trigger,tag_exposure_index,tag_frame_number,tag_timestamp,shield_step,shield_dir,shield_enable);
    
    // Module arguments
    input wire  clock;
    input wire  i2c_ctrl_start;
    input wire  i2c_ctrl_read;
    input wire  [6:0] i2c_target_addr7;
    input wire  [7:0] i2c_reg_addr_addr;
    input wire  [15:0] i2c_write_data_data;
    input wire  [15:0] i2c_clock_div_half_period;
    input wire  [23:0] i2c_timeout_cycles;
    output reg  [15:0] i2c_read_data_data;
    output reg  i2c_status_busy;
    output reg  i2c_status_done_set;
    output reg  i2c_status_nack_set;
    output reg  i2c_status_timeout_set;
    output reg  i2c_status_bus_stuck_set;
    output reg  i2c_status_refused_set;
    input wire  seq_ctrl_start;
    input wire  seq_ctrl_abort;
    input wire  seq_ctrl_ext_trigger;
    input wire  [3:0] seq_count_exposures;
    input wire  [31:0] seq_shield_limit_cycles;
    input wire  [15:0] seq_shield_steps_steps;
    input wire  [23:0] seq_shield_step_period_cycles;
    input wire  [15:0] seq_trigger_pulse_cycles;
    input wire  [19:0] seq_exp_shutter_width_rows$0;
    input wire  [19:0] seq_exp_shutter_width_rows$1;
    input wire  [19:0] seq_exp_shutter_width_rows$2;
    input wire  [19:0] seq_exp_shutter_width_rows$3;
    input wire  [19:0] seq_exp_shutter_width_rows$4;
    input wire  [19:0] seq_exp_shutter_width_rows$5;
    input wire  [19:0] seq_exp_shutter_width_rows$6;
    input wire  [19:0] seq_exp_shutter_width_rows$7;
    input wire  [12:0] seq_exp_shutter_delay_value$0;
    input wire  [12:0] seq_exp_shutter_delay_value$1;
    input wire  [12:0] seq_exp_shutter_delay_value$2;
    input wire  [12:0] seq_exp_shutter_delay_value$3;
    input wire  [12:0] seq_exp_shutter_delay_value$4;
    input wire  [12:0] seq_exp_shutter_delay_value$5;
    input wire  [12:0] seq_exp_shutter_delay_value$6;
    input wire  [12:0] seq_exp_shutter_delay_value$7;
    input wire  [15:0] seq_exp_gain_code$0;
    input wire  [15:0] seq_exp_gain_code$1;
    input wire  [15:0] seq_exp_gain_code$2;
    input wire  [15:0] seq_exp_gain_code$3;
    input wire  [15:0] seq_exp_gain_code$4;
    input wire  [15:0] seq_exp_gain_code$5;
    input wire  [15:0] seq_exp_gain_code$6;
    input wire  [15:0] seq_exp_gain_code$7;
    output reg  seq_status_busy;
    output reg  [2:0] seq_status_index;
    output reg  seq_status_shield_open;
    output reg  seq_status_done_set;
    output reg  seq_status_shield_limit_hit_set;
    output reg  seq_status_i2c_error_set;
    output reg  seq_status_refused_set;
    output reg  seq_status_aborted_set;
    output reg  [31:0] seq_frame_number_value;
    input wire  [63:0] time_cycles;
    input wire  ext_trigger;
    input wire  frame_valid;
    input wire  scl_in;
    input wire  sda_in;
    output reg  scl_low;
    output reg  sda_low;
    output reg  trigger;
    output reg  [2:0] tag_exposure_index;
    output reg  [31:0] tag_frame_number;
    output reg  [63:0] tag_timestamp;
    output reg  shield_step;
    output reg  shield_dir;
    output reg  shield_enable;
    
    // Stub signals
    reg  master$clock;
    reg  master$start;
    reg  master$read;
    reg  [6:0] master$device;
    reg  [7:0] master$reg_addr;
    reg  [15:0] master$write_data;
    reg  [15:0] master$half_period;
    reg  [23:0] master$timeout_cycles;
    reg  master$scl_in;
    reg  master$sda_in;
    wire  master$scl_low;
    wire  master$sda_low;
    wire  master$busy;
    wire  master$done;
    wire  master$nack;
    wire  master$timeout;
    wire  master$bus_stuck;
    wire  [15:0] master$read_data;
    reg  sequencer$clock;
    reg  sequencer$start;
    reg  sequencer$abort_request;
    reg  sequencer$ext_trigger_enable;
    reg  sequencer$ext_trigger;
    reg  [3:0] sequencer$exposures;
    reg  [31:0] sequencer$shield_limit_cycles;
    reg  [15:0] sequencer$shield_steps;
    reg  [23:0] sequencer$step_period_cycles;
    reg  [15:0] sequencer$trigger_pulse_cycles;
    reg  [19:0] sequencer$shutter_width$0;
    reg  [19:0] sequencer$shutter_width$1;
    reg  [19:0] sequencer$shutter_width$2;
    reg  [19:0] sequencer$shutter_width$3;
    reg  [19:0] sequencer$shutter_width$4;
    reg  [19:0] sequencer$shutter_width$5;
    reg  [19:0] sequencer$shutter_width$6;
    reg  [19:0] sequencer$shutter_width$7;
    reg  [12:0] sequencer$shutter_delay$0;
    reg  [12:0] sequencer$shutter_delay$1;
    reg  [12:0] sequencer$shutter_delay$2;
    reg  [12:0] sequencer$shutter_delay$3;
    reg  [12:0] sequencer$shutter_delay$4;
    reg  [12:0] sequencer$shutter_delay$5;
    reg  [12:0] sequencer$shutter_delay$6;
    reg  [12:0] sequencer$shutter_delay$7;
    reg  [15:0] sequencer$gain$0;
    reg  [15:0] sequencer$gain$1;
    reg  [15:0] sequencer$gain$2;
    reg  [15:0] sequencer$gain$3;
    reg  [15:0] sequencer$gain$4;
    reg  [15:0] sequencer$gain$5;
    reg  [15:0] sequencer$gain$6;
    reg  [15:0] sequencer$gain$7;
    reg  [63:0] sequencer$time_cycles;
    reg  sequencer$frame_valid;
    wire  sequencer$i2c_start;
    wire  [7:0] sequencer$i2c_reg_addr;
    wire  [15:0] sequencer$i2c_write_data;
    wire  sequencer$i2c_owner;
    reg  sequencer$i2c_busy;
    reg  sequencer$i2c_done;
    reg  sequencer$i2c_error;
    wire  sequencer$busy;
    wire  [2:0] sequencer$index;
    wire  sequencer$shield_open;
    wire  sequencer$done;
    wire  sequencer$shield_limit_hit;
    wire  sequencer$i2c_failed;
    wire  sequencer$refused;
    wire  sequencer$aborted;
    wire  [31:0] sequencer$frame_number;
    wire  sequencer$trigger;
    wire  [2:0] sequencer$tag_exposure_index;
    wire  [31:0] sequencer$tag_frame_number;
    wire  [63:0] sequencer$tag_timestamp;
    wire  sequencer$shield_step;
    wire  sequencer$shield_dir;
    wire  sequencer$shield_enable;
    reg  hps_txn$d;
    wire  hps_txn$q;
    reg  hps_txn$clock;
    reg  refused_r$d;
    wire  refused_r$q;
    reg  refused_r$clock;
    
    // Sub module instances
    skylux_core$sensor$master master(
        .clock(master$clock),
        .start(master$start),
        .read(master$read),
        .device(master$device),
        .reg_addr(master$reg_addr),
        .write_data(master$write_data),
        .half_period(master$half_period),
        .timeout_cycles(master$timeout_cycles),
        .scl_in(master$scl_in),
        .sda_in(master$sda_in),
        .scl_low(master$scl_low),
        .sda_low(master$sda_low),
        .busy(master$busy),
        .done(master$done),
        .nack(master$nack),
        .timeout(master$timeout),
        .bus_stuck(master$bus_stuck),
        .read_data(master$read_data)
    );
    skylux_core$sensor$sequencer sequencer(
        .clock(sequencer$clock),
        .start(sequencer$start),
        .abort_request(sequencer$abort_request),
        .ext_trigger_enable(sequencer$ext_trigger_enable),
        .ext_trigger(sequencer$ext_trigger),
        .exposures(sequencer$exposures),
        .shield_limit_cycles(sequencer$shield_limit_cycles),
        .shield_steps(sequencer$shield_steps),
        .step_period_cycles(sequencer$step_period_cycles),
        .trigger_pulse_cycles(sequencer$trigger_pulse_cycles),
        .shutter_width$0(sequencer$shutter_width$0),
        .shutter_width$1(sequencer$shutter_width$1),
        .shutter_width$2(sequencer$shutter_width$2),
        .shutter_width$3(sequencer$shutter_width$3),
        .shutter_width$4(sequencer$shutter_width$4),
        .shutter_width$5(sequencer$shutter_width$5),
        .shutter_width$6(sequencer$shutter_width$6),
        .shutter_width$7(sequencer$shutter_width$7),
        .shutter_delay$0(sequencer$shutter_delay$0),
        .shutter_delay$1(sequencer$shutter_delay$1),
        .shutter_delay$2(sequencer$shutter_delay$2),
        .shutter_delay$3(sequencer$shutter_delay$3),
        .shutter_delay$4(sequencer$shutter_delay$4),
        .shutter_delay$5(sequencer$shutter_delay$5),
        .shutter_delay$6(sequencer$shutter_delay$6),
        .shutter_delay$7(sequencer$shutter_delay$7),
        .gain$0(sequencer$gain$0),
        .gain$1(sequencer$gain$1),
        .gain$2(sequencer$gain$2),
        .gain$3(sequencer$gain$3),
        .gain$4(sequencer$gain$4),
        .gain$5(sequencer$gain$5),
        .gain$6(sequencer$gain$6),
        .gain$7(sequencer$gain$7),
        .time_cycles(sequencer$time_cycles),
        .frame_valid(sequencer$frame_valid),
        .i2c_start(sequencer$i2c_start),
        .i2c_reg_addr(sequencer$i2c_reg_addr),
        .i2c_write_data(sequencer$i2c_write_data),
        .i2c_owner(sequencer$i2c_owner),
        .i2c_busy(sequencer$i2c_busy),
        .i2c_done(sequencer$i2c_done),
        .i2c_error(sequencer$i2c_error),
        .busy(sequencer$busy),
        .index(sequencer$index),
        .shield_open(sequencer$shield_open),
        .done(sequencer$done),
        .shield_limit_hit(sequencer$shield_limit_hit),
        .i2c_failed(sequencer$i2c_failed),
        .refused(sequencer$refused),
        .aborted(sequencer$aborted),
        .frame_number(sequencer$frame_number),
        .trigger(sequencer$trigger),
        .tag_exposure_index(sequencer$tag_exposure_index),
        .tag_frame_number(sequencer$tag_frame_number),
        .tag_timestamp(sequencer$tag_timestamp),
        .shield_step(sequencer$shield_step),
        .shield_dir(sequencer$shield_dir),
        .shield_enable(sequencer$shield_enable)
    );
    skylux_core$sensor$hps_txn hps_txn(
        .d(hps_txn$d),
        .q(hps_txn$q),
        .clock(hps_txn$clock)
    );
    skylux_core$sensor$refused_r refused_r(
        .d(refused_r$d),
        .q(refused_r$q),
        .clock(refused_r$clock)
    );
    
    // Update code
    always @(*) begin
        hps_txn$clock = clock;
        refused_r$clock = clock;
        hps_txn$d = hps_txn$q;
        refused_r$d = refused_r$q;
        master$clock = clock;
        sequencer$clock = clock;
        refused_r$d = 1'b0;
        master$device = i2c_target_addr7;
        master$half_period = i2c_clock_div_half_period;
        master$timeout_cycles = i2c_timeout_cycles;
        master$scl_in = scl_in;
        master$sda_in = sda_in;
        if (sequencer$i2c_owner) begin
            master$start = sequencer$i2c_start;
            master$read = 1'b0;
            master$reg_addr = sequencer$i2c_reg_addr;
            master$write_data = sequencer$i2c_write_data;
        end
        else begin
            master$start = i2c_ctrl_start & ~master$busy;
            master$read = i2c_ctrl_read;
            master$reg_addr = i2c_reg_addr_addr;
            master$write_data = i2c_write_data_data;
        end
        if (master$done) begin
            hps_txn$d = 1'b0;
        end
        if (i2c_ctrl_start) begin
            if (sequencer$i2c_owner | master$busy) begin
                refused_r$d = 1'b1;
            end
            else begin
                hps_txn$d = 1'b1;
            end
        end
        sequencer$start = seq_ctrl_start;
        sequencer$abort_request = seq_ctrl_abort;
        sequencer$ext_trigger_enable = seq_ctrl_ext_trigger;
        sequencer$ext_trigger = ext_trigger;
        sequencer$exposures = seq_count_exposures;
        sequencer$shield_limit_cycles = seq_shield_limit_cycles;
        sequencer$shield_steps = seq_shield_steps_steps;
        sequencer$step_period_cycles = seq_shield_step_period_cycles;
        sequencer$trigger_pulse_cycles = seq_trigger_pulse_cycles;
        sequencer$shutter_width$0 = seq_exp_shutter_width_rows$0;
        sequencer$shutter_delay$0 = seq_exp_shutter_delay_value$0;
        sequencer$gain$0 = seq_exp_gain_code$0;
        sequencer$shutter_width$1 = seq_exp_shutter_width_rows$1;
        sequencer$shutter_delay$1 = seq_exp_shutter_delay_value$1;
        sequencer$gain$1 = seq_exp_gain_code$1;
        sequencer$shutter_width$2 = seq_exp_shutter_width_rows$2;
        sequencer$shutter_delay$2 = seq_exp_shutter_delay_value$2;
        sequencer$gain$2 = seq_exp_gain_code$2;
        sequencer$shutter_width$3 = seq_exp_shutter_width_rows$3;
        sequencer$shutter_delay$3 = seq_exp_shutter_delay_value$3;
        sequencer$gain$3 = seq_exp_gain_code$3;
        sequencer$shutter_width$4 = seq_exp_shutter_width_rows$4;
        sequencer$shutter_delay$4 = seq_exp_shutter_delay_value$4;
        sequencer$gain$4 = seq_exp_gain_code$4;
        sequencer$shutter_width$5 = seq_exp_shutter_width_rows$5;
        sequencer$shutter_delay$5 = seq_exp_shutter_delay_value$5;
        sequencer$gain$5 = seq_exp_gain_code$5;
        sequencer$shutter_width$6 = seq_exp_shutter_width_rows$6;
        sequencer$shutter_delay$6 = seq_exp_shutter_delay_value$6;
        sequencer$gain$6 = seq_exp_gain_code$6;
        sequencer$shutter_width$7 = seq_exp_shutter_width_rows$7;
        sequencer$shutter_delay$7 = seq_exp_shutter_delay_value$7;
        sequencer$gain$7 = seq_exp_gain_code$7;
        sequencer$time_cycles = time_cycles;
        sequencer$frame_valid = frame_valid;
        sequencer$i2c_busy = master$busy;
        sequencer$i2c_done = master$done & ~hps_txn$q;
        sequencer$i2c_error = (master$nack | master$timeout) | master$bus_stuck;
        i2c_read_data_data = master$read_data;
        i2c_status_busy = master$busy | sequencer$i2c_owner;
        i2c_status_done_set = master$done & hps_txn$q;
        i2c_status_nack_set = master$nack;
        i2c_status_timeout_set = master$timeout;
        i2c_status_bus_stuck_set = master$bus_stuck;
        i2c_status_refused_set = refused_r$q;
        scl_low = master$scl_low;
        sda_low = master$sda_low;
        seq_status_busy = sequencer$busy;
        seq_status_index = sequencer$index;
        seq_status_shield_open = sequencer$shield_open;
        seq_status_done_set = sequencer$done;
        seq_status_shield_limit_hit_set = sequencer$shield_limit_hit;
        seq_status_i2c_error_set = sequencer$i2c_failed;
        seq_status_refused_set = sequencer$refused;
        seq_status_aborted_set = sequencer$aborted;
        seq_frame_number_value = sequencer$frame_number;
        trigger = sequencer$trigger;
        tag_exposure_index = sequencer$tag_exposure_index;
        tag_frame_number = sequencer$tag_frame_number;
        tag_timestamp = sequencer$tag_timestamp;
        shield_step = sequencer$shield_step;
        shield_dir = sequencer$shield_dir;
        shield_enable = sequencer$shield_enable;
    end
    
endmodule // skylux_core$sensor


module skylux_core$sensor$hps_txn(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$hps_txn


module skylux_core$sensor$master(clock,start,read,device,reg_addr,write_data,half_period,timeout_cycles,scl_in,sda_in,scl_low,sda_low,busy,done,nack,timeout,bus_stuck,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  start;
    input wire  read;
    input wire  [6:0] device;
    input wire  [7:0] reg_addr;
    input wire  [15:0] write_data;
    input wire  [15:0] half_period;
    input wire  [23:0] timeout_cycles;
    input wire  scl_in;
    input wire  sda_in;
    output reg  scl_low;
    output reg  sda_low;
    output reg  busy;
    output reg  done;
    output reg  nack;
    output reg  timeout;
    output reg  bus_stuck;
    output reg  [15:0] read_data;
    
    // Stub signals
    reg  scl_sync0$d;
    wire  scl_sync0$q;
    reg  scl_sync0$clock;
    reg  scl_sync1$d;
    wire  scl_sync1$q;
    reg  scl_sync1$clock;
    reg  sda_sync0$d;
    wire  sda_sync0$q;
    reg  sda_sync0$clock;
    reg  sda_sync1$d;
    wire  sda_sync1$q;
    reg  sda_sync1$clock;
    reg  scl_r$d;
    wire  scl_r$q;
    reg  scl_r$clock;
    reg  sda_r$d;
    wire  sda_r$q;
    reg  sda_r$clock;
    reg  busy_r$d;
    wire  busy_r$q;
    reg  busy_r$clock;
    reg  rd$d;
    wire  rd$q;
    reg  rd$clock;
    reg  [7:0] dev$d;
    wire  [7:0] dev$q;
    reg  dev$clock;
    reg  [7:0] ra$d;
    wire  [7:0] ra$q;
    reg  ra$clock;
    reg  [15:0] wd$d;
    wire  [15:0] wd$q;
    reg  wd$clock;
    reg  [15:0] quarter_len$d;
    wire  [15:0] quarter_len$q;
    reg  quarter_len$clock;
    reg  [3:0] step$d;
    wire  [3:0] step$q;
    reg  step$clock;
    reg  [3:0] bit_no$d;
    wire  [3:0] bit_no$q;
    reg  bit_no$clock;
    reg  [1:0] quarter$d;
    wire  [1:0] quarter$q;
    reg  quarter$clock;
    reg  [15:0] count$d;
    wire  [15:0] count$q;
    reg  count$clock;
    reg  [23:0] watchdog$d;
    wire  [23:0] watchdog$q;
    reg  watchdog$clock;
    reg  failed_nack$d;
    wire  failed_nack$q;
    reg  failed_nack$clock;
    reg  [15:0] rdata$d;
    wire  [15:0] rdata$q;
    reg  rdata$clock;
    reg  done_r$d;
    wire  done_r$q;
    reg  done_r$clock;
    reg  nack_r$d;
    wire  nack_r$q;
    reg  nack_r$clock;
    reg  timeout_r$d;
    wire  timeout_r$q;
    reg  timeout_r$clock;
    reg  stuck_r$d;
    wire  stuck_r$q;
    reg  stuck_r$clock;
    
    // Local signals
    reg  [1:0] kind;
    reg  [7:0] tx;
    reg  [7:0] tx_shifted;
    reg  rx;
    reg  ack_level;
    reg  [3:0] last_step;
    reg  level;
    reg  want_scl;
    reg  want_sda;
    reg  [15:0] count_next;
    reg  [3:0] step_next;
    reg  [3:0] bit_next;
    reg  [15:0] half_in;
    
    // Sub module instances
    skylux_core$sensor$master$scl_sync0 scl_sync0(
        .d(scl_sync0$d),
        .q(scl_sync0$q),
        .clock(scl_sync0$clock)
    );
    skylux_core$sensor$master$scl_sync1 scl_sync1(
        .d(scl_sync1$d),
        .q(scl_sync1$q),
        .clock(scl_sync1$clock)
    );
    skylux_core$sensor$master$sda_sync0 sda_sync0(
        .d(sda_sync0$d),
        .q(sda_sync0$q),
        .clock(sda_sync0$clock)
    );
    skylux_core$sensor$master$sda_sync1 sda_sync1(
        .d(sda_sync1$d),
        .q(sda_sync1$q),
        .clock(sda_sync1$clock)
    );
    skylux_core$sensor$master$scl_r scl_r(
        .d(scl_r$d),
        .q(scl_r$q),
        .clock(scl_r$clock)
    );
    skylux_core$sensor$master$sda_r sda_r(
        .d(sda_r$d),
        .q(sda_r$q),
        .clock(sda_r$clock)
    );
    skylux_core$sensor$master$busy_r busy_r(
        .d(busy_r$d),
        .q(busy_r$q),
        .clock(busy_r$clock)
    );
    skylux_core$sensor$master$rd rd(
        .d(rd$d),
        .q(rd$q),
        .clock(rd$clock)
    );
    skylux_core$sensor$master$dev dev(
        .d(dev$d),
        .q(dev$q),
        .clock(dev$clock)
    );
    skylux_core$sensor$master$ra ra(
        .d(ra$d),
        .q(ra$q),
        .clock(ra$clock)
    );
    skylux_core$sensor$master$wd wd(
        .d(wd$d),
        .q(wd$q),
        .clock(wd$clock)
    );
    skylux_core$sensor$master$quarter_len quarter_len(
        .d(quarter_len$d),
        .q(quarter_len$q),
        .clock(quarter_len$clock)
    );
    skylux_core$sensor$master$step step(
        .d(step$d),
        .q(step$q),
        .clock(step$clock)
    );
    skylux_core$sensor$master$bit_no bit_no(
        .d(bit_no$d),
        .q(bit_no$q),
        .clock(bit_no$clock)
    );
    skylux_core$sensor$master$quarter quarter(
        .d(quarter$d),
        .q(quarter$q),
        .clock(quarter$clock)
    );
    skylux_core$sensor$master$count count(
        .d(count$d),
        .q(count$q),
        .clock(count$clock)
    );
    skylux_core$sensor$master$watchdog watchdog(
        .d(watchdog$d),
        .q(watchdog$q),
        .clock(watchdog$clock)
    );
    skylux_core$sensor$master$failed_nack failed_nack(
        .d(failed_nack$d),
        .q(failed_nack$q),
        .clock(failed_nack$clock)
    );
    skylux_core$sensor$master$rdata rdata(
        .d(rdata$d),
        .q(rdata$q),
        .clock(rdata$clock)
    );
    skylux_core$sensor$master$done_r done_r(
        .d(done_r$d),
        .q(done_r$q),
        .clock(done_r$clock)
    );
    skylux_core$sensor$master$nack_r nack_r(
        .d(nack_r$d),
        .q(nack_r$q),
        .clock(nack_r$clock)
    );
    skylux_core$sensor$master$timeout_r timeout_r(
        .d(timeout_r$d),
        .q(timeout_r$q),
        .clock(timeout_r$clock)
    );
    skylux_core$sensor$master$stuck_r stuck_r(
        .d(stuck_r$d),
        .q(stuck_r$q),
        .clock(stuck_r$clock)
    );
    
    // Update code
    always @(*) begin
        scl_sync0$clock = clock;
        scl_sync1$clock = clock;
        sda_sync0$clock = clock;
        sda_sync1$clock = clock;
        scl_r$clock = clock;
        sda_r$clock = clock;
        busy_r$clock = clock;
        rd$clock = clock;
        dev$clock = clock;
        ra$clock = clock;
        wd$clock = clock;
        quarter_len$clock = clock;
        step$clock = clock;
        bit_no$clock = clock;
        quarter$clock = clock;
        count$clock = clock;
        watchdog$clock = clock;
        failed_nack$clock = clock;
        rdata$clock = clock;
        done_r$clock = clock;
        nack_r$clock = clock;
        timeout_r$clock = clock;
        stuck_r$clock = clock;
        scl_sync0$d = scl_sync0$q;
        scl_sync1$d = scl_sync1$q;
        sda_sync0$d = sda_sync0$q;
        sda_sync1$d = sda_sync1$q;
        scl_r$d = scl_r$q;
        sda_r$d = sda_r$q;
        busy_r$d = busy_r$q;
        rd$d = rd$q;
        dev$d = dev$q;
        ra$d = ra$q;
        wd$d = wd$q;
        quarter_len$d = quarter_len$q;
        step$d = step$q;
        bit_no$d = bit_no$q;
        quarter$d = quarter$q;
        count$d = count$q;
        watchdog$d = watchdog$q;
        failed_nack$d = failed_nack$q;
        rdata$d = rdata$q;
        done_r$d = done_r$q;
        nack_r$d = nack_r$q;
        timeout_r$d = timeout_r$q;
        stuck_r$d = stuck_r$q;
        scl_sync0$d = scl_in;
        scl_sync1$d = scl_sync0$q;
        sda_sync0$d = sda_in;
        sda_sync1$d = sda_sync0$q;
        done_r$d = 1'b0;
        nack_r$d = 1'b0;
        timeout_r$d = 1'b0;
        stuck_r$d = 1'b0;
        kind = 32'h2;
        tx = 32'h0;
        rx = 1'b0;
        ack_level = 1'b1;
        if (rd$q) begin
            last_step = 32'h7;
        end
        else begin
            last_step = 32'h5;
        end
        case (step$q)
            0:
                begin
                    kind = 32'h0;
                end
            1:
                begin
                    tx = dev$q << 32'h1;
                end
            2:
                begin
                    tx = ra$q;
                end
            3:
                begin
                    if (rd$q) begin
                        kind = 32'h1;
                    end
                    else begin
                        tx = wd$q[(32'h8)+:(8)];
                    end
                end
            4:
                begin
                    if (rd$q) begin
                        tx = (dev$q << 32'h1) | 32'h1;
                    end
                    else begin
                        tx = wd$q[(32'h0)+:(8)];
                    end
                end
            5:
                begin
                    if (rd$q) begin
                        rx = 1'b1;
                        ack_level = 1'b0;
                    end
                    else begin
                        kind = 32'h3;
                    end
                end
            6:
                begin
                    rx = 1'b1;
                end
            default:
                begin
                    kind = 32'h3;
                end
        endcase
        tx_shifted = tx << bit_no$q;
        level = 1'b1;
        if (bit_no$q == 32'h8) begin
            if (rx) begin
                level = ack_level;
            end
        end
        else if (~rx) begin
            level = tx_shifted[32'h7];
        end
        want_scl = 1'b0;
        want_sda = sda_r$q;
        case (kind)
            0:
                begin
                    want_scl = quarter$q != 32'h3;
                    want_sda = quarter$q < 32'h2;
                end
            1:
                begin
                    want_scl = quarter$q >= 32'h2;
                    if (quarter$q == 32'h1) begin
                        want_sda = 1'b1;
                    end
                    if (quarter$q == 32'h3) begin
                        want_sda = 1'b0;
                    end
                end
            2:
                begin
                    want_scl = quarter$q >= 32'h2;
                    if (quarter$q != 32'h0) begin
                        want_sda = level;
                    end
                end
            default:
                begin
                    want_scl = quarter$q >= 32'h2;
                    if (quarter$q == 32'h1) begin
                        want_sda = 1'b0;
                    end
                    if (quarter$q == 32'h3) begin
                        want_sda = 1'b1;
                    end
                end
        endcase
        count_next = count$q + 32'h1;
        step_next = step$q + 32'h1;
        bit_next = bit_no$q + 32'h1;
        half_in = half_period >> 32'h1;
        if (busy_r$q) begin
            watchdog$d = watchdog$q + 32'h1;
            scl_r$d = want_scl;
            sda_r$d = want_sda;
            if (watchdog$q >= timeout_cycles) begin
                busy_r$d = 1'b0;
                done_r$d = 1'b1;
                timeout_r$d = 1'b1;
                scl_r$d = 1'b1;
                sda_r$d = 1'b1;
            end
            else if (scl_r$q & ~scl_sync1$q) begin
            end
            else if (count_next < quarter_len$q) begin
                count$d = count_next;
            end
            else begin
                count$d = 32'h0;
                quarter$d = quarter$q + 32'h1;
                if ((sda_r$q & ~sda_sync1$q) & (((kind == 32'h0) & (quarter$q == 32'h1)) | ((kind == 32'h1) & (quarter$q == 32'h2)) | (((kind == 32'h2) & (quarter$q == 32'h3)) & (~rx & (bit_no$q != 32'h8))))) begin
                    busy_r$d = 1'b0;
                    done_r$d = 1'b1;
                    stuck_r$d = 1'b1;
                    scl_r$d = 1'b1;
                    sda_r$d = 1'b1;
                end
                else if (quarter$q == 32'h3) begin
                    if (kind == 32'h3) begin
                        busy_r$d = 1'b0;
                        done_r$d = 1'b1;
                        nack_r$d = failed_nack$q;
                    end
                    else if (kind == 32'h2) begin
                        if (bit_no$q == 32'h8) begin
                            bit_no$d = 32'h0;
                            if (~rx & sda_sync1$q) begin
                                failed_nack$d = 1'b1;
                                step$d = last_step;
                            end
                            else begin
                                step$d = step_next;
                            end
                        end
                        else begin
                            bit_no$d = bit_next;
                            if (rx) begin
                                rdata$d = (rdata$q << 32'h1) | ((sda_sync1$q) & 16'hffff);
                            end
                        end
                    end
                    else begin
                        step$d = step_next;
                    end
                end
            end
        end
        else if (start) begin
            busy_r$d = 1'b1;
            rd$d = read;
            dev$d = ((device) & 8'hff);
            ra$d = reg_addr;
            wd$d = write_data;
            if (half_in == 32'h0) begin
                quarter_len$d = 32'h1;
            end
            else begin
                quarter_len$d = half_in;
            end
            step$d = 32'h0;
            bit_no$d = 32'h0;
            quarter$d = 32'h0;
            count$d = 32'h0;
            watchdog$d = 32'h0;
            failed_nack$d = 1'b0;
            if (read) begin
                rdata$d = 32'h0;
            end
        end
        scl_low = ~scl_r$q;
        sda_low = ~sda_r$q;
        busy = busy_r$q;
        done = done_r$q;
        nack = nack_r$q;
        timeout = timeout_r$q;
        bus_stuck = stuck_r$q;
        read_data = rdata$q;
    end
    
endmodule // skylux_core$sensor$master


module skylux_core$sensor$master$bit_no(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$master$bit_no


module skylux_core$sensor$master$busy_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$master$busy_r


module skylux_core$sensor$master$count(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$master$count


module skylux_core$sensor$master$dev(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$master$dev


module skylux_core$sensor$master$done_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$master$done_r


module skylux_core$sensor$master$failed_nack(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$master$failed_nack


module skylux_core$sensor$master$nack_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$master$nack_r


module skylux_core$sensor$master$quarter(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$master$quarter


module skylux_core$sensor$master$quarter_len(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$master$quarter_len


module skylux_core$sensor$master$ra(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$master$ra


module skylux_core$sensor$master$rd(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$master$rd


module skylux_core$sensor$master$rdata(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$master$rdata


module skylux_core$sensor$master$scl_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 1'b1;
    
    // Stub signals
    reg  dff$d;
    wire  dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$sensor$master$scl_r$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$sensor$master$scl_r


module skylux_core$sensor$master$scl_r$dff(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$master$scl_r$dff


module skylux_core$sensor$master$scl_sync0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 1'b1;
    
    // Stub signals
    reg  dff$d;
    wire  dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$sensor$master$scl_sync0$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$sensor$master$scl_sync0


module skylux_core$sensor$master$scl_sync0$dff(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$master$scl_sync0$dff


module skylux_core$sensor$master$scl_sync1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 1'b1;
    
    // Stub signals
    reg  dff$d;
    wire  dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$sensor$master$scl_sync1$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$sensor$master$scl_sync1


module skylux_core$sensor$master$scl_sync1$dff(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$master$scl_sync1$dff


module skylux_core$sensor$master$sda_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 1'b1;
    
    // Stub signals
    reg  dff$d;
    wire  dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$sensor$master$sda_r$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$sensor$master$sda_r


module skylux_core$sensor$master$sda_r$dff(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$master$sda_r$dff


module skylux_core$sensor$master$sda_sync0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 1'b1;
    
    // Stub signals
    reg  dff$d;
    wire  dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$sensor$master$sda_sync0$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$sensor$master$sda_sync0


module skylux_core$sensor$master$sda_sync0$dff(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$master$sda_sync0$dff


module skylux_core$sensor$master$sda_sync1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Constant declarations
    localparam  init = 1'b1;
    
    // Stub signals
    reg  dff$d;
    wire  dff$q;
    reg  dff$clock;
    
    // Sub module instances
    skylux_core$sensor$master$sda_sync1$dff dff(
        .d(dff$d),
        .q(dff$q),
        .clock(dff$clock)
    );
    
    // Update code
    always @(*) begin
        dff$clock = clock;
        q = dff$q ^ init;
        dff$d = d ^ init;
    end
    
endmodule // skylux_core$sensor$master$sda_sync1


module skylux_core$sensor$master$sda_sync1$dff(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$master$sda_sync1$dff


module skylux_core$sensor$master$step(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$master$step


module skylux_core$sensor$master$stuck_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$master$stuck_r


module skylux_core$sensor$master$timeout_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$master$timeout_r


module skylux_core$sensor$master$watchdog(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$master$watchdog


module skylux_core$sensor$master$wd(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$master$wd


module skylux_core$sensor$refused_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$refused_r


module skylux_core$sensor$sequencer(clock,start,abort_request,ext_trigger_enable,ext_trigger,exposures,shield_limit_cycles,shield_steps,step_period_cycles,trigger_pulse_cycles,shutter_width$0,shutter_width$1,shutter_width$2,shutter_width$3,shutter_width$4,shutter_width$5,shutter_width$6,shutter_width$7,shutter_delay$0,shutter_delay$1,shutter_delay$2,shutter_delay$3,shutter_delay$4,shutter_delay$5,shutter_delay$6,shutter_delay$7,gain$0,gain$1,gain$2,gain$3,gain$4,gain$5,gain$6,gain$7,time_cycles,frame_valid,i2c_start,i2c_reg_addr,i2c_write_data,i2c_owner,i2c_busy,i2c_done,i2c_error,busy,index,shield_open,done,shield_limit_hit,i2c_failed,refused,aborted,frame_number,trigger,tag_exposure_index,tag_frame_number,tag_timestamp,shield_step,shield_dir,shield_enable);
    
    // Module arguments
    input wire  clock;
    input wire  start;
    input wire  abort_request;
    input wire  ext_trigger_enable;
    input wire  ext_trigger;
    input wire  [3:0] exposures;
    input wire  [31:0] shield_limit_cycles;
    input wire  [15:0] shield_steps;
    input wire  [23:0] step_period_cycles;
    input wire  [15:0] trigger_pulse_cycles;
    input wire  [19:0] shutter_width$0;
    input wire  [19:0] shutter_width$1;
    input wire  [19:0] shutter_width$2;
    input wire  [19:0] shutter_width$3;
    input wire  [19:0] shutter_width$4;
    input wire  [19:0] shutter_width$5;
    input wire  [19:0] shutter_width$6;
    input wire  [19:0] shutter_width$7;
    input wire  [12:0] shutter_delay$0;
    input wire  [12:0] shutter_delay$1;
    input wire  [12:0] shutter_delay$2;
    input wire  [12:0] shutter_delay$3;
    input wire  [12:0] shutter_delay$4;
    input wire  [12:0] shutter_delay$5;
    input wire  [12:0] shutter_delay$6;
    input wire  [12:0] shutter_delay$7;
    input wire  [15:0] gain$0;
    input wire  [15:0] gain$1;
    input wire  [15:0] gain$2;
    input wire  [15:0] gain$3;
    input wire  [15:0] gain$4;
    input wire  [15:0] gain$5;
    input wire  [15:0] gain$6;
    input wire  [15:0] gain$7;
    input wire  [63:0] time_cycles;
    input wire  frame_valid;
    output reg  i2c_start;
    output reg  [7:0] i2c_reg_addr;
    output reg  [15:0] i2c_write_data;
    output reg  i2c_owner;
    input wire  i2c_busy;
    input wire  i2c_done;
    input wire  i2c_error;
    output reg  busy;
    output reg  [2:0] index;
    output reg  shield_open;
    output reg  done;
    output reg  shield_limit_hit;
    output reg  i2c_failed;
    output reg  refused;
    output reg  aborted;
    output reg  [31:0] frame_number;
    output reg  trigger;
    output reg  [2:0] tag_exposure_index;
    output reg  [31:0] tag_frame_number;
    output reg  [63:0] tag_timestamp;
    output reg  shield_step;
    output reg  shield_dir;
    output reg  shield_enable;
    
    // Enums
    localparam SeqState$Idle = 0;
    localparam SeqState$Open = 1;
    localparam SeqState$Write = 2;
    localparam SeqState$Trigger = 3;
    localparam SeqState$WaitFrameStart = 4;
    localparam SeqState$WaitFrameEnd = 5;
    localparam SeqState$Close = 6;
    
    // Stub signals
    reg  [2:0] state$d;
    wire  [2:0] state$q;
    reg  state$clock;
    reg  ext_sync0$d;
    wire  ext_sync0$q;
    reg  ext_sync0$clock;
    reg  ext_sync1$d;
    wire  ext_sync1$q;
    reg  ext_sync1$clock;
    reg  ext_prev$d;
    wire  ext_prev$q;
    reg  ext_prev$clock;
    reg  fv_sync0$d;
    wire  fv_sync0$q;
    reg  fv_sync0$clock;
    reg  fv_sync1$d;
    wire  fv_sync1$q;
    reg  fv_sync1$clock;
    reg  fv_prev$d;
    wire  fv_prev$q;
    reg  fv_prev$clock;
    reg  [3:0] count_l$d;
    wire  [3:0] count_l$q;
    reg  count_l$clock;
    reg  [31:0] limit_l$d;
    wire  [31:0] limit_l$q;
    reg  limit_l$clock;
    reg  [15:0] steps_l$d;
    wire  [15:0] steps_l$q;
    reg  steps_l$clock;
    reg  [23:0] period_l$d;
    wire  [23:0] period_l$q;
    reg  period_l$clock;
    reg  [15:0] pulse_l$d;
    wire  [15:0] pulse_l$q;
    reg  pulse_l$clock;
    reg  [19:0] sw_l$0$d;
    wire  [19:0] sw_l$0$q;
    reg  sw_l$0$clock;
    reg  [19:0] sw_l$1$d;
    wire  [19:0] sw_l$1$q;
    reg  sw_l$1$clock;
    reg  [19:0] sw_l$2$d;
    wire  [19:0] sw_l$2$q;
    reg  sw_l$2$clock;
    reg  [19:0] sw_l$3$d;
    wire  [19:0] sw_l$3$q;
    reg  sw_l$3$clock;
    reg  [19:0] sw_l$4$d;
    wire  [19:0] sw_l$4$q;
    reg  sw_l$4$clock;
    reg  [19:0] sw_l$5$d;
    wire  [19:0] sw_l$5$q;
    reg  sw_l$5$clock;
    reg  [19:0] sw_l$6$d;
    wire  [19:0] sw_l$6$q;
    reg  sw_l$6$clock;
    reg  [19:0] sw_l$7$d;
    wire  [19:0] sw_l$7$q;
    reg  sw_l$7$clock;
    reg  [12:0] sd_l$0$d;
    wire  [12:0] sd_l$0$q;
    reg  sd_l$0$clock;
    reg  [12:0] sd_l$1$d;
    wire  [12:0] sd_l$1$q;
    reg  sd_l$1$clock;
    reg  [12:0] sd_l$2$d;
    wire  [12:0] sd_l$2$q;
    reg  sd_l$2$clock;
    reg  [12:0] sd_l$3$d;
    wire  [12:0] sd_l$3$q;
    reg  sd_l$3$clock;
    reg  [12:0] sd_l$4$d;
    wire  [12:0] sd_l$4$q;
    reg  sd_l$4$clock;
    reg  [12:0] sd_l$5$d;
    wire  [12:0] sd_l$5$q;
    reg  sd_l$5$clock;
    reg  [12:0] sd_l$6$d;
    wire  [12:0] sd_l$6$q;
    reg  sd_l$6$clock;
    reg  [12:0] sd_l$7$d;
    wire  [12:0] sd_l$7$q;
    reg  sd_l$7$clock;
    reg  [15:0] gain_l$0$d;
    wire  [15:0] gain_l$0$q;
    reg  gain_l$0$clock;
    reg  [15:0] gain_l$1$d;
    wire  [15:0] gain_l$1$q;
    reg  gain_l$1$clock;
    reg  [15:0] gain_l$2$d;
    wire  [15:0] gain_l$2$q;
    reg  gain_l$2$clock;
    reg  [15:0] gain_l$3$d;
    wire  [15:0] gain_l$3$q;
    reg  gain_l$3$clock;
    reg  [15:0] gain_l$4$d;
    wire  [15:0] gain_l$4$q;
    reg  gain_l$4$clock;
    reg  [15:0] gain_l$5$d;
    wire  [15:0] gain_l$5$q;
    reg  gain_l$5$clock;
    reg  [15:0] gain_l$6$d;
    wire  [15:0] gain_l$6$q;
    reg  gain_l$6$clock;
    reg  [15:0] gain_l$7$d;
    wire  [15:0] gain_l$7$q;
    reg  gain_l$7$clock;
    reg  [2:0] idx$d;
    wire  [2:0] idx$q;
    reg  idx$clock;
    reg  [1:0] write_no$d;
    wire  [1:0] write_no$q;
    reg  write_no$clock;
    reg  requested$d;
    wire  requested$q;
    reg  requested$clock;
    reg  [15:0] position$d;
    wire  [15:0] position$q;
    reg  position$clock;
    reg  [23:0] step_timer$d;
    wire  [23:0] step_timer$q;
    reg  step_timer$clock;
    reg  step_pin$d;
    wire  step_pin$q;
    reg  step_pin$clock;
    reg  [31:0] open_cycles$d;
    wire  [31:0] open_cycles$q;
    reg  open_cycles$clock;
    reg  [47:0] close_cost$d;
    wire  [47:0] close_cost$q;
    reg  close_cost$clock;
    reg  [15:0] pulse_timer$d;
    wire  [15:0] pulse_timer$q;
    reg  pulse_timer$clock;
    reg  [31:0] frames$d;
    wire  [31:0] frames$q;
    reg  frames$clock;
    reg  [2:0] tag_idx$d;
    wire  [2:0] tag_idx$q;
    reg  tag_idx$clock;
    reg  [31:0] tag_frame$d;
    wire  [31:0] tag_frame$q;
    reg  tag_frame$clock;
    reg  [63:0] tag_time$d;
    wire  [63:0] tag_time$q;
    reg  tag_time$clock;
    reg  done_r$d;
    wire  done_r$q;
    reg  done_r$clock;
    reg  limit_r$d;
    wire  limit_r$q;
    reg  limit_r$clock;
    reg  i2c_fail_r$d;
    wire  i2c_fail_r$q;
    reg  i2c_fail_r$clock;
    reg  refused_r$d;
    wire  refused_r$q;
    reg  refused_r$clock;
    reg  aborted_r$d;
    wire  aborted_r$q;
    reg  aborted_r$clock;
    reg  i2c_start_r$d;
    wire  i2c_start_r$q;
    reg  i2c_start_r$clock;
    
    // Local signals
    reg  go;
    reg  [19:0] cur_sw;
    reg  [12:0] cur_sd;
    reg  [15:0] cur_gain;
    reg  [47:0] budget_now;
    reg  [47:0] budget_next_step;
    reg  [47:0] limit48;
    reg  [47:0] period48;
    reg  over_budget;
    reg  step_would_exceed;
    reg  [23:0] timer_next;
    reg  [23:0] half_period;
    reg  [15:0] pulse_next;
    reg  [3:0] idx_next;
    reg  [31:0] open_next;
    
    // Sub module instances
    skylux_core$sensor$sequencer$state state(
        .d(state$d),
        .q(state$q),
        .clock(state$clock)
    );
    skylux_core$sensor$sequencer$ext_sync0 ext_sync0(
        .d(ext_sync0$d),
        .q(ext_sync0$q),
        .clock(ext_sync0$clock)
    );
    skylux_core$sensor$sequencer$ext_sync1 ext_sync1(
        .d(ext_sync1$d),
        .q(ext_sync1$q),
        .clock(ext_sync1$clock)
    );
    skylux_core$sensor$sequencer$ext_prev ext_prev(
        .d(ext_prev$d),
        .q(ext_prev$q),
        .clock(ext_prev$clock)
    );
    skylux_core$sensor$sequencer$fv_sync0 fv_sync0(
        .d(fv_sync0$d),
        .q(fv_sync0$q),
        .clock(fv_sync0$clock)
    );
    skylux_core$sensor$sequencer$fv_sync1 fv_sync1(
        .d(fv_sync1$d),
        .q(fv_sync1$q),
        .clock(fv_sync1$clock)
    );
    skylux_core$sensor$sequencer$fv_prev fv_prev(
        .d(fv_prev$d),
        .q(fv_prev$q),
        .clock(fv_prev$clock)
    );
    skylux_core$sensor$sequencer$count_l count_l(
        .d(count_l$d),
        .q(count_l$q),
        .clock(count_l$clock)
    );
    skylux_core$sensor$sequencer$limit_l limit_l(
        .d(limit_l$d),
        .q(limit_l$q),
        .clock(limit_l$clock)
    );
    skylux_core$sensor$sequencer$steps_l steps_l(
        .d(steps_l$d),
        .q(steps_l$q),
        .clock(steps_l$clock)
    );
    skylux_core$sensor$sequencer$period_l period_l(
        .d(period_l$d),
        .q(period_l$q),
        .clock(period_l$clock)
    );
    skylux_core$sensor$sequencer$pulse_l pulse_l(
        .d(pulse_l$d),
        .q(pulse_l$q),
        .clock(pulse_l$clock)
    );
    skylux_core$sensor$sequencer$sw_l$0 sw_l$0(
        .d(sw_l$0$d),
        .q(sw_l$0$q),
        .clock(sw_l$0$clock)
    );
    skylux_core$sensor$sequencer$sw_l$1 sw_l$1(
        .d(sw_l$1$d),
        .q(sw_l$1$q),
        .clock(sw_l$1$clock)
    );
    skylux_core$sensor$sequencer$sw_l$2 sw_l$2(
        .d(sw_l$2$d),
        .q(sw_l$2$q),
        .clock(sw_l$2$clock)
    );
    skylux_core$sensor$sequencer$sw_l$3 sw_l$3(
        .d(sw_l$3$d),
        .q(sw_l$3$q),
        .clock(sw_l$3$clock)
    );
    skylux_core$sensor$sequencer$sw_l$4 sw_l$4(
        .d(sw_l$4$d),
        .q(sw_l$4$q),
        .clock(sw_l$4$clock)
    );
    skylux_core$sensor$sequencer$sw_l$5 sw_l$5(
        .d(sw_l$5$d),
        .q(sw_l$5$q),
        .clock(sw_l$5$clock)
    );
    skylux_core$sensor$sequencer$sw_l$6 sw_l$6(
        .d(sw_l$6$d),
        .q(sw_l$6$q),
        .clock(sw_l$6$clock)
    );
    skylux_core$sensor$sequencer$sw_l$7 sw_l$7(
        .d(sw_l$7$d),
        .q(sw_l$7$q),
        .clock(sw_l$7$clock)
    );
    skylux_core$sensor$sequencer$sd_l$0 sd_l$0(
        .d(sd_l$0$d),
        .q(sd_l$0$q),
        .clock(sd_l$0$clock)
    );
    skylux_core$sensor$sequencer$sd_l$1 sd_l$1(
        .d(sd_l$1$d),
        .q(sd_l$1$q),
        .clock(sd_l$1$clock)
    );
    skylux_core$sensor$sequencer$sd_l$2 sd_l$2(
        .d(sd_l$2$d),
        .q(sd_l$2$q),
        .clock(sd_l$2$clock)
    );
    skylux_core$sensor$sequencer$sd_l$3 sd_l$3(
        .d(sd_l$3$d),
        .q(sd_l$3$q),
        .clock(sd_l$3$clock)
    );
    skylux_core$sensor$sequencer$sd_l$4 sd_l$4(
        .d(sd_l$4$d),
        .q(sd_l$4$q),
        .clock(sd_l$4$clock)
    );
    skylux_core$sensor$sequencer$sd_l$5 sd_l$5(
        .d(sd_l$5$d),
        .q(sd_l$5$q),
        .clock(sd_l$5$clock)
    );
    skylux_core$sensor$sequencer$sd_l$6 sd_l$6(
        .d(sd_l$6$d),
        .q(sd_l$6$q),
        .clock(sd_l$6$clock)
    );
    skylux_core$sensor$sequencer$sd_l$7 sd_l$7(
        .d(sd_l$7$d),
        .q(sd_l$7$q),
        .clock(sd_l$7$clock)
    );
    skylux_core$sensor$sequencer$gain_l$0 gain_l$0(
        .d(gain_l$0$d),
        .q(gain_l$0$q),
        .clock(gain_l$0$clock)
    );
    skylux_core$sensor$sequencer$gain_l$1 gain_l$1(
        .d(gain_l$1$d),
        .q(gain_l$1$q),
        .clock(gain_l$1$clock)
    );
    skylux_core$sensor$sequencer$gain_l$2 gain_l$2(
        .d(gain_l$2$d),
        .q(gain_l$2$q),
        .clock(gain_l$2$clock)
    );
    skylux_core$sensor$sequencer$gain_l$3 gain_l$3(
        .d(gain_l$3$d),
        .q(gain_l$3$q),
        .clock(gain_l$3$clock)
    );
    skylux_core$sensor$sequencer$gain_l$4 gain_l$4(
        .d(gain_l$4$d),
        .q(gain_l$4$q),
        .clock(gain_l$4$clock)
    );
    skylux_core$sensor$sequencer$gain_l$5 gain_l$5(
        .d(gain_l$5$d),
        .q(gain_l$5$q),
        .clock(gain_l$5$clock)
    );
    skylux_core$sensor$sequencer$gain_l$6 gain_l$6(
        .d(gain_l$6$d),
        .q(gain_l$6$q),
        .clock(gain_l$6$clock)
    );
    skylux_core$sensor$sequencer$gain_l$7 gain_l$7(
        .d(gain_l$7$d),
        .q(gain_l$7$q),
        .clock(gain_l$7$clock)
    );
    skylux_core$sensor$sequencer$idx idx(
        .d(idx$d),
        .q(idx$q),
        .clock(idx$clock)
    );
    skylux_core$sensor$sequencer$write_no write_no(
        .d(write_no$d),
        .q(write_no$q),
        .clock(write_no$clock)
    );
    skylux_core$sensor$sequencer$requested requested(
        .d(requested$d),
        .q(requested$q),
        .clock(requested$clock)
    );
    skylux_core$sensor$sequencer$position position(
        .d(position$d),
        .q(position$q),
        .clock(position$clock)
    );
    skylux_core$sensor$sequencer$step_timer step_timer(
        .d(step_timer$d),
        .q(step_timer$q),
        .clock(step_timer$clock)
    );
    skylux_core$sensor$sequencer$step_pin step_pin(
        .d(step_pin$d),
        .q(step_pin$q),
        .clock(step_pin$clock)
    );
    skylux_core$sensor$sequencer$open_cycles open_cycles(
        .d(open_cycles$d),
        .q(open_cycles$q),
        .clock(open_cycles$clock)
    );
    skylux_core$sensor$sequencer$close_cost close_cost(
        .d(close_cost$d),
        .q(close_cost$q),
        .clock(close_cost$clock)
    );
    skylux_core$sensor$sequencer$pulse_timer pulse_timer(
        .d(pulse_timer$d),
        .q(pulse_timer$q),
        .clock(pulse_timer$clock)
    );
    skylux_core$sensor$sequencer$frames frames(
        .d(frames$d),
        .q(frames$q),
        .clock(frames$clock)
    );
    skylux_core$sensor$sequencer$tag_idx tag_idx(
        .d(tag_idx$d),
        .q(tag_idx$q),
        .clock(tag_idx$clock)
    );
    skylux_core$sensor$sequencer$tag_frame tag_frame(
        .d(tag_frame$d),
        .q(tag_frame$q),
        .clock(tag_frame$clock)
    );
    skylux_core$sensor$sequencer$tag_time tag_time(
        .d(tag_time$d),
        .q(tag_time$q),
        .clock(tag_time$clock)
    );
    skylux_core$sensor$sequencer$done_r done_r(
        .d(done_r$d),
        .q(done_r$q),
        .clock(done_r$clock)
    );
    skylux_core$sensor$sequencer$limit_r limit_r(
        .d(limit_r$d),
        .q(limit_r$q),
        .clock(limit_r$clock)
    );
    skylux_core$sensor$sequencer$i2c_fail_r i2c_fail_r(
        .d(i2c_fail_r$d),
        .q(i2c_fail_r$q),
        .clock(i2c_fail_r$clock)
    );
    skylux_core$sensor$sequencer$refused_r refused_r(
        .d(refused_r$d),
        .q(refused_r$q),
        .clock(refused_r$clock)
    );
    skylux_core$sensor$sequencer$aborted_r aborted_r(
        .d(aborted_r$d),
        .q(aborted_r$q),
        .clock(aborted_r$clock)
    );
    skylux_core$sensor$sequencer$i2c_start_r i2c_start_r(
        .d(i2c_start_r$d),
        .q(i2c_start_r$q),
        .clock(i2c_start_r$clock)
    );
    
    // Update code
    always @(*) begin
        state$clock = clock;
        ext_sync0$clock = clock;
        ext_sync1$clock = clock;
        ext_prev$clock = clock;
        fv_sync0$clock = clock;
        fv_sync1$clock = clock;
        fv_prev$clock = clock;
        count_l$clock = clock;
        limit_l$clock = clock;
        steps_l$clock = clock;
        period_l$clock = clock;
        pulse_l$clock = clock;
        idx$clock = clock;
        write_no$clock = clock;
        requested$clock = clock;
        position$clock = clock;
        step_timer$clock = clock;
        step_pin$clock = clock;
        open_cycles$clock = clock;
        close_cost$clock = clock;
        pulse_timer$clock = clock;
        frames$clock = clock;
        tag_idx$clock = clock;
        tag_frame$clock = clock;
        tag_time$clock = clock;
        done_r$clock = clock;
        limit_r$clock = clock;
        i2c_fail_r$clock = clock;
        refused_r$clock = clock;
        aborted_r$clock = clock;
        i2c_start_r$clock = clock;
        state$d = state$q;
        ext_sync0$d = ext_sync0$q;
        ext_sync1$d = ext_sync1$q;
        ext_prev$d = ext_prev$q;
        fv_sync0$d = fv_sync0$q;
        fv_sync1$d = fv_sync1$q;
        fv_prev$d = fv_prev$q;
        count_l$d = count_l$q;
        limit_l$d = limit_l$q;
        steps_l$d = steps_l$q;
        period_l$d = period_l$q;
        pulse_l$d = pulse_l$q;
        idx$d = idx$q;
        write_no$d = write_no$q;
        requested$d = requested$q;
        position$d = position$q;
        step_timer$d = step_timer$q;
        step_pin$d = step_pin$q;
        open_cycles$d = open_cycles$q;
        close_cost$d = close_cost$q;
        pulse_timer$d = pulse_timer$q;
        frames$d = frames$q;
        tag_idx$d = tag_idx$q;
        tag_frame$d = tag_frame$q;
        tag_time$d = tag_time$q;
        done_r$d = done_r$q;
        limit_r$d = limit_r$q;
        i2c_fail_r$d = i2c_fail_r$q;
        refused_r$d = refused_r$q;
        aborted_r$d = aborted_r$q;
        i2c_start_r$d = i2c_start_r$q;
        sw_l$0$clock = clock;
        sd_l$0$clock = clock;
        gain_l$0$clock = clock;
        sw_l$0$d = sw_l$0$q;
        sd_l$0$d = sd_l$0$q;
        gain_l$0$d = gain_l$0$q;
        sw_l$1$clock = clock;
        sd_l$1$clock = clock;
        gain_l$1$clock = clock;
        sw_l$1$d = sw_l$1$q;
        sd_l$1$d = sd_l$1$q;
        gain_l$1$d = gain_l$1$q;
        sw_l$2$clock = clock;
        sd_l$2$clock = clock;
        gain_l$2$clock = clock;
        sw_l$2$d = sw_l$2$q;
        sd_l$2$d = sd_l$2$q;
        gain_l$2$d = gain_l$2$q;
        sw_l$3$clock = clock;
        sd_l$3$clock = clock;
        gain_l$3$clock = clock;
        sw_l$3$d = sw_l$3$q;
        sd_l$3$d = sd_l$3$q;
        gain_l$3$d = gain_l$3$q;
        sw_l$4$clock = clock;
        sd_l$4$clock = clock;
        gain_l$4$clock = clock;
        sw_l$4$d = sw_l$4$q;
        sd_l$4$d = sd_l$4$q;
        gain_l$4$d = gain_l$4$q;
        sw_l$5$clock = clock;
        sd_l$5$clock = clock;
        gain_l$5$clock = clock;
        sw_l$5$d = sw_l$5$q;
        sd_l$5$d = sd_l$5$q;
        gain_l$5$d = gain_l$5$q;
        sw_l$6$clock = clock;
        sd_l$6$clock = clock;
        gain_l$6$clock = clock;
        sw_l$6$d = sw_l$6$q;
        sd_l$6$d = sd_l$6$q;
        gain_l$6$d = gain_l$6$q;
        sw_l$7$clock = clock;
        sd_l$7$clock = clock;
        gain_l$7$clock = clock;
        sw_l$7$d = sw_l$7$q;
        sd_l$7$d = sd_l$7$q;
        gain_l$7$d = gain_l$7$q;
        ext_sync0$d = ext_trigger;
        ext_sync1$d = ext_sync0$q;
        ext_prev$d = ext_sync1$q;
        fv_sync0$d = frame_valid;
        fv_sync1$d = fv_sync0$q;
        fv_prev$d = fv_sync1$q;
        done_r$d = 1'b0;
        limit_r$d = 1'b0;
        i2c_fail_r$d = 1'b0;
        refused_r$d = 1'b0;
        aborted_r$d = 1'b0;
        i2c_start_r$d = 1'b0;
        go = start | ((ext_trigger_enable & ext_sync1$q) & ~ext_prev$q);
        cur_sw = sw_l$0$q;
        cur_sd = sd_l$0$q;
        cur_gain = gain_l$0$q;
        if (idx$q == 0) begin
            cur_sw = sw_l$0$q;
            cur_sd = sd_l$0$q;
            cur_gain = gain_l$0$q;
        end
        if (idx$q == 1) begin
            cur_sw = sw_l$1$q;
            cur_sd = sd_l$1$q;
            cur_gain = gain_l$1$q;
        end
        if (idx$q == 2) begin
            cur_sw = sw_l$2$q;
            cur_sd = sd_l$2$q;
            cur_gain = gain_l$2$q;
        end
        if (idx$q == 3) begin
            cur_sw = sw_l$3$q;
            cur_sd = sd_l$3$q;
            cur_gain = gain_l$3$q;
        end
        if (idx$q == 4) begin
            cur_sw = sw_l$4$q;
            cur_sd = sd_l$4$q;
            cur_gain = gain_l$4$q;
        end
        if (idx$q == 5) begin
            cur_sw = sw_l$5$q;
            cur_sd = sd_l$5$q;
            cur_gain = gain_l$5$q;
        end
        if (idx$q == 6) begin
            cur_sw = sw_l$6$q;
            cur_sd = sd_l$6$q;
            cur_gain = gain_l$6$q;
        end
        if (idx$q == 7) begin
            cur_sw = sw_l$7$q;
            cur_sd = sd_l$7$q;
            cur_gain = gain_l$7$q;
        end
        i2c_reg_addr = 32'h8;
        i2c_write_data = ((cur_sw[(32'h10)+:(4)]) & 16'hffff);
        case (write_no$q)
            0:
                begin
                end
            1:
                begin
                    i2c_reg_addr = 32'h9;
                    i2c_write_data = cur_sw[(32'h0)+:(16)];
                end
            2:
                begin
                    i2c_reg_addr = 32'hc;
                    i2c_write_data = ((cur_sd) & 16'hffff);
                end
            default:
                begin
                    i2c_reg_addr = 32'h35;
                    i2c_write_data = cur_gain;
                end
        endcase
        limit48 = ((limit_l$q) & 48'hffffffffffff);
        period48 = ((period_l$q) & 48'hffffffffffff);
        budget_now = ((open_cycles$q) & 48'hffffffffffff) + close_cost$q;
        budget_next_step = budget_now + period48;
        over_budget = (position$q != 32'h0) & (budget_now >= limit48);
        step_would_exceed = budget_next_step >= limit48;
        open_next = open_cycles$q + 32'h1;
        if (position$q != 32'h0) begin
            open_cycles$d = open_next;
        end
        timer_next = step_timer$q + 32'h1;
        half_period = period_l$q >> 32'h1;
        pulse_next = pulse_timer$q + 32'h1;
        idx_next = ((idx$q) & 4'hf) + 32'h1;
        if (step_timer$q != 32'h0) begin
            if (timer_next >= period_l$q) begin
                step_timer$d = 32'h0;
                step_pin$d = 1'b0;
            end
            else begin
                step_timer$d = timer_next;
                if (timer_next >= half_period) begin
                    step_pin$d = 1'b0;
                end
            end
        end
        case (state$q)
            SeqState$Idle:
                begin
                    step_pin$d = 1'b0;
                    step_timer$d = 32'h0;
                    if (go) begin
                        if ((exposures == 32'h0) | (exposures > 32'h8)) begin
                            refused_r$d = 1'b1;
                        end
                        else begin
                            state$d = SeqState$Open;
                            count_l$d = exposures;
                            if (shield_limit_cycles < 64'h3473bc0) begin
                                limit_l$d = shield_limit_cycles;
                            end
                            else begin
                                limit_l$d = 64'h3473bc0;
                            end
                            steps_l$d = shield_steps;
                            if (step_period_cycles < 32'h2) begin
                                period_l$d = 32'h2;
                            end
                            else begin
                                period_l$d = step_period_cycles;
                            end
                            if (trigger_pulse_cycles == 32'h0) begin
                                pulse_l$d = 32'h1;
                            end
                            else begin
                                pulse_l$d = trigger_pulse_cycles;
                            end
                            sw_l$0$d = shutter_width$0;
                            sd_l$0$d = shutter_delay$0;
                            gain_l$0$d = gain$0;
                            sw_l$1$d = shutter_width$1;
                            sd_l$1$d = shutter_delay$1;
                            gain_l$1$d = gain$1;
                            sw_l$2$d = shutter_width$2;
                            sd_l$2$d = shutter_delay$2;
                            gain_l$2$d = gain$2;
                            sw_l$3$d = shutter_width$3;
                            sd_l$3$d = shutter_delay$3;
                            gain_l$3$d = gain$3;
                            sw_l$4$d = shutter_width$4;
                            sd_l$4$d = shutter_delay$4;
                            gain_l$4$d = gain$4;
                            sw_l$5$d = shutter_width$5;
                            sd_l$5$d = shutter_delay$5;
                            gain_l$5$d = gain$5;
                            sw_l$6$d = shutter_width$6;
                            sd_l$6$d = shutter_delay$6;
                            gain_l$6$d = gain$6;
                            sw_l$7$d = shutter_width$7;
                            sd_l$7$d = shutter_delay$7;
                            gain_l$7$d = gain$7;
                            idx$d = 32'h0;
                            write_no$d = 32'h0;
                            requested$d = 1'b0;
                            open_cycles$d = 32'h0;
                            close_cost$d = 32'h0;
                        end
                    end
                end
            SeqState$Open:
                begin
                    if (step_timer$q == 32'h0) begin
                        if (position$q >= steps_l$q) begin
                            state$d = SeqState$Write;
                        end
                        else if (step_would_exceed) begin
                            limit_r$d = 1'b1;
                            state$d = SeqState$Close;
                        end
                        else begin
                            position$d = position$q + 32'h1;
                            close_cost$d = close_cost$q + period48;
                            step_pin$d = 1'b1;
                            step_timer$d = 32'h1;
                        end
                    end
                end
            SeqState$Write:
                begin
                    if (~requested$q) begin
                        if (~i2c_busy) begin
                            i2c_start_r$d = 1'b1;
                            requested$d = 1'b1;
                        end
                    end
                    else if (i2c_done) begin
                        requested$d = 1'b0;
                        if (i2c_error) begin
                            i2c_fail_r$d = 1'b1;
                            state$d = SeqState$Close;
                        end
                        else if (write_no$q == 32'h3) begin
                            write_no$d = 32'h0;
                            state$d = SeqState$Trigger;
                            pulse_timer$d = 32'h0;
                            tag_idx$d = idx$q;
                            tag_frame$d = frames$q;
                            tag_time$d = time_cycles;
                            frames$d = frames$q + 32'h1;
                        end
                        else begin
                            write_no$d = write_no$q + 32'h1;
                        end
                    end
                end
            SeqState$Trigger:
                begin
                    pulse_timer$d = pulse_next;
                    if (pulse_next >= pulse_l$q) begin
                        state$d = SeqState$WaitFrameStart;
                    end
                end
            SeqState$WaitFrameStart:
                begin
                    if (fv_sync1$q & ~fv_prev$q) begin
                        state$d = SeqState$WaitFrameEnd;
                    end
                end
            SeqState$WaitFrameEnd:
                begin
                    if (~fv_sync1$q & fv_prev$q) begin
                        if (idx_next >= count_l$q) begin
                            state$d = SeqState$Close;
                        end
                        else begin
                            idx$d = idx$q + 32'h1;
                            state$d = SeqState$Write;
                        end
                    end
                end
            SeqState$Close:
                begin
                    if (i2c_done) begin
                        requested$d = 1'b0;
                    end
                    if (step_timer$q == 32'h0) begin
                        if (position$q != 32'h0) begin
                            position$d = position$q - 32'h1;
                            close_cost$d = close_cost$q - period48;
                            step_pin$d = 1'b1;
                            step_timer$d = 32'h1;
                        end
                        else if (~requested$q | i2c_done) begin
                            requested$d = 1'b0;
                            done_r$d = 1'b1;
                            state$d = SeqState$Idle;
                        end
                    end
                end
        endcase
        if ((state$q != SeqState$Idle) & (state$q != SeqState$Close)) begin
            if (go) begin
                refused_r$d = 1'b1;
            end
            if (abort_request) begin
                aborted_r$d = 1'b1;
                state$d = SeqState$Close;
                step_timer$d = 32'h0;
                step_pin$d = 1'b0;
            end
            else if (over_budget) begin
                limit_r$d = 1'b1;
                state$d = SeqState$Close;
                step_timer$d = 32'h0;
                step_pin$d = 1'b0;
            end
        end
        else if ((state$q == SeqState$Close) & go) begin
            refused_r$d = 1'b1;
        end
        i2c_start = i2c_start_r$q;
        i2c_owner = state$q != SeqState$Idle;
        busy = state$q != SeqState$Idle;
        index = idx$q;
        shield_open = position$q != 32'h0;
        done = done_r$q;
        shield_limit_hit = limit_r$q;
        i2c_failed = i2c_fail_r$q;
        refused = refused_r$q;
        aborted = aborted_r$q;
        frame_number = frames$q;
        trigger = state$q == SeqState$Trigger;
        tag_exposure_index = tag_idx$q;
        tag_frame_number = tag_frame$q;
        tag_timestamp = tag_time$q;
        shield_step = step_pin$q;
        shield_dir = (state$q != SeqState$Close) & (state$q != SeqState$Idle);
        shield_enable = state$q != SeqState$Idle;
    end
    
endmodule // skylux_core$sensor$sequencer


module skylux_core$sensor$sequencer$aborted_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$aborted_r


module skylux_core$sensor$sequencer$close_cost(d,q,clock);
    
    // Module arguments
    input wire  [47:0] d;
    output reg  [47:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 48'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$close_cost


module skylux_core$sensor$sequencer$count_l(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$count_l


module skylux_core$sensor$sequencer$done_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$done_r


module skylux_core$sensor$sequencer$ext_prev(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$ext_prev


module skylux_core$sensor$sequencer$ext_sync0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$ext_sync0


module skylux_core$sensor$sequencer$ext_sync1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$ext_sync1


module skylux_core$sensor$sequencer$frames(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$frames


module skylux_core$sensor$sequencer$fv_prev(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$fv_prev


module skylux_core$sensor$sequencer$fv_sync0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$fv_sync0


module skylux_core$sensor$sequencer$fv_sync1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$fv_sync1


module skylux_core$sensor$sequencer$gain_l$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$gain_l$0


module skylux_core$sensor$sequencer$gain_l$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$gain_l$1


module skylux_core$sensor$sequencer$gain_l$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$gain_l$2


module skylux_core$sensor$sequencer$gain_l$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$gain_l$3


module skylux_core$sensor$sequencer$gain_l$4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$gain_l$4


module skylux_core$sensor$sequencer$gain_l$5(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$gain_l$5


module skylux_core$sensor$sequencer$gain_l$6(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$gain_l$6


module skylux_core$sensor$sequencer$gain_l$7(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$gain_l$7


module skylux_core$sensor$sequencer$i2c_fail_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$i2c_fail_r


module skylux_core$sensor$sequencer$i2c_start_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$i2c_start_r


module skylux_core$sensor$sequencer$idx(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$idx


module skylux_core$sensor$sequencer$limit_l(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$limit_l


module skylux_core$sensor$sequencer$limit_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$limit_r


module skylux_core$sensor$sequencer$open_cycles(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$open_cycles


module skylux_core$sensor$sequencer$period_l(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$period_l


module skylux_core$sensor$sequencer$position(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$position


module skylux_core$sensor$sequencer$pulse_l(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$pulse_l


module skylux_core$sensor$sequencer$pulse_timer(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$pulse_timer


module skylux_core$sensor$sequencer$refused_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$refused_r


module skylux_core$sensor$sequencer$requested(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$requested


module skylux_core$sensor$sequencer$sd_l$0(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$sd_l$0


module skylux_core$sensor$sequencer$sd_l$1(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$sd_l$1


module skylux_core$sensor$sequencer$sd_l$2(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$sd_l$2


module skylux_core$sensor$sequencer$sd_l$3(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$sd_l$3


module skylux_core$sensor$sequencer$sd_l$4(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$sd_l$4


module skylux_core$sensor$sequencer$sd_l$5(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$sd_l$5


module skylux_core$sensor$sequencer$sd_l$6(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$sd_l$6


module skylux_core$sensor$sequencer$sd_l$7(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$sd_l$7


module skylux_core$sensor$sequencer$state(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Enums
    localparam SeqState$Idle = 0;
    localparam SeqState$Open = 1;
    localparam SeqState$Write = 2;
    localparam SeqState$Trigger = 3;
    localparam SeqState$WaitFrameStart = 4;
    localparam SeqState$WaitFrameEnd = 5;
    localparam SeqState$Close = 6;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$state


module skylux_core$sensor$sequencer$step_pin(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$step_pin


module skylux_core$sensor$sequencer$step_timer(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$step_timer


module skylux_core$sensor$sequencer$steps_l(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$steps_l


module skylux_core$sensor$sequencer$sw_l$0(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$sw_l$0


module skylux_core$sensor$sequencer$sw_l$1(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$sw_l$1


module skylux_core$sensor$sequencer$sw_l$2(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$sw_l$2


module skylux_core$sensor$sequencer$sw_l$3(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$sw_l$3


module skylux_core$sensor$sequencer$sw_l$4(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$sw_l$4


module skylux_core$sensor$sequencer$sw_l$5(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$sw_l$5


module skylux_core$sensor$sequencer$sw_l$6(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$sw_l$6


module skylux_core$sensor$sequencer$sw_l$7(d,q,clock);
    
    // Module arguments
    input wire  [19:0] d;
    output reg  [19:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 20'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$sw_l$7


module skylux_core$sensor$sequencer$tag_frame(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$tag_frame


module skylux_core$sensor$sequencer$tag_idx(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$tag_idx


module skylux_core$sensor$sequencer$tag_time(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$tag_time


module skylux_core$sensor$sequencer$write_no(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$sensor$sequencer$write_no


module skylux_core$strobe_meta(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$strobe_meta


module skylux_core$strobe_sync(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$strobe_sync


module skylux_core$time_base(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // skylux_core$time_base
