/* SPDX-License-Identifier: Apache-2.0 */
/* drcc.h: portable C99 driver for the DRCC dual-redundancy CAN 2.0B controller
 * (its own Wishbone register view, rtl-out/drcc_regs.h). Register access goes
 * through two hooks the user provides; nothing here touches memory directly.
 *
 * Features newer than the map 1.0 need the instance's VERSION.minor (read by
 * drcc_init()): transmit abort (drcc_abort) needs minor 2, manual bus-off
 * recovery (drcc_config.busoff_manual, drcc_recover) minor 3, DMR first-copy
 * delivery (drcc_config.dmr_first_copy) minor 4. On an older
 * instance those calls return DRCC_E_UNSUPPORTED and write nothing. */
#ifndef DRCC_DRIVER_H
#define DRCC_DRIVER_H

#include <stddef.h>
#include <stdint.h>

#include "drcc_regs.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Reads the 32-bit register at byte offset `offset` (a DRCC_*_OFFSET). */
typedef uint32_t (*drcc_read32_fn)(void *ctx, uint32_t offset);
/** Writes the 32-bit register at byte offset `offset` as a whole word. */
typedef void (*drcc_write32_fn)(void *ctx, uint32_t offset, uint32_t value);

/** Result codes: 0 is success, every error is negative. */
enum drcc_result {
    DRCC_OK = 0,
    /** An argument is out of range (identifier, DLC, mode, field value). */
    DRCC_E_INVAL = -1,
    /** No bit timing gives exactly this bit rate from this clock. */
    DRCC_E_NO_TIMING = -2,
    /** The ID register does not read "DRCC". */
    DRCC_E_NODEV = -3,
    /** The controller refused a write (read back differs): e.g. DMR or star
     * mode on a top generated without it, redundancy with a listen-only
     * channel, or configuration outside reset mode. */
    DRCC_E_REFUSED = -4,
    /** The target TX queue is full. */
    DRCC_E_FULL = -5,
    /** The RX FIFO is empty. */
    DRCC_E_EMPTY = -6,
    /** The controller is not in the state the call needs (reset mode). */
    DRCC_E_STATE = -7,
    /** VERSION.major is not 1: a register map this driver does not know. */
    DRCC_E_VERSION = -8,
    /** The instance's VERSION.minor is below the one the feature needs
     * (DRCC_MINOR_ABORT, DRCC_MINOR_BUSOFF_MANUAL, DRCC_MINOR_FIRST_COPY);
     * nothing was written. */
    DRCC_E_UNSUPPORTED = -9
};

/** VERSION.minor from which TX_CMD.abort_a/abort_b exist (contract §11.5). */
#define DRCC_MINOR_ABORT 2u
/** VERSION.minor from which CTRL.busoff_manual and TX_CMD.recover_a/recover_b
 * exist (contract §11.6). */
#define DRCC_MINOR_BUSOFF_MANUAL 3u
/** VERSION.minor from which CTRL.first_copy exists (DMR contract §8.1). */
#define DRCC_MINOR_FIRST_COPY 4u

/** A set of channels (a bit mask) for drcc_abort() and drcc_recover(). */
enum drcc_channels {
    DRCC_CH_A = 1,   /**< channel A (queue 0) */
    DRCC_CH_B = 2,   /**< channel B (queue 1) */
    DRCC_CH_BOTH = 3 /**< both, in one register write */
};

/** VERSION and SIZES, read by drcc_init(). */
typedef struct drcc_ident {
    uint8_t major;          /**< VERSION.major (1) */
    uint8_t minor;          /**< VERSION.minor (registers added since 1.0) */
    uint8_t rx_fifo_depth;  /**< SIZES: RX FIFO entries */
    uint8_t tx_queue_depth; /**< SIZES: entries of each TX queue */
    uint8_t history;        /**< SIZES: duplicate-removal history entries */
    uint8_t mailboxes;      /**< SIZES: DMR mailboxes (0 or 16) */
    uint8_t dmr;            /**< SIZES: 1 if CTRL.dmr can be set */
    uint8_t star;           /**< SIZES: 1 if CTRL.star can be set */
} drcc_ident;

/** One controller: the user's hooks and what the driver remembers. */
typedef struct drcc_dev {
    drcc_read32_fn read32;   /**< register read hook */
    drcc_write32_fn write32; /**< register write hook */
    void *ctx;               /**< passed to both hooks */
    uint32_t ctrl;           /**< CTRL configuration last written (reset_mode 0) */
    unsigned tx_queue_depth; /**< frames per TX queue (SIZES.tx_queue_depth) */
    drcc_ident ident;        /**< VERSION and SIZES as drcc_init() read them */
} drcc_dev;

/** Bit timing in real units (not the register's minus-one codes). */
typedef struct drcc_bit_timing {
    uint16_t brp;   /**< prescaler: one time quantum = brp clocks, 1..1024 */
    uint8_t tseg1;  /**< PROP_SEG + PHASE_SEG1 in tq, 1..16 */
    uint8_t tseg2;  /**< PHASE_SEG2 in tq, 1..8 */
    uint8_t sjw;    /**< resynchronisation jump width in tq, 1..4 */
    uint8_t triple; /**< 1 = three samples per bit */
} drcc_bit_timing;

/** Operating mode (CTRL.redundancy, CTRL.dmr). */
typedef enum drcc_mode {
    DRCC_MODE_NORMAL = 0,     /**< two independent controllers, queue per channel */
    DRCC_MODE_REDUNDANCY = 1, /**< one logical controller on a channel pair */
    DRCC_MODE_DMR = 2         /**< CiA 701 DMR (generation option: not drcc_small) */
} drcc_mode;

/** Channel mode (CTRL.mode_a, CTRL.mode_b; values of DRCC_CTRL_MODE_A_*). */
typedef enum drcc_chan_mode {
    DRCC_CHAN_NORMAL = DRCC_CTRL_MODE_A_NORMAL,
    DRCC_CHAN_LISTEN_ONLY = DRCC_CTRL_MODE_A_LISTEN_ONLY,
    DRCC_CHAN_SELF_TEST = DRCC_CTRL_MODE_A_SELF_TEST,
    DRCC_CHAN_LOOPBACK = DRCC_CTRL_MODE_A_LOOPBACK
} drcc_chan_mode;

/** Everything drcc_configure() writes. Start from drcc_config_default(). */
typedef struct drcc_config {
    drcc_bit_timing timing;  /**< both channels */
    uint8_t ewl;             /**< error warning limit (BTR.ewl) */
    drcc_mode mode;          /**< normal, redundancy or DMR */
    unsigned policy;         /**< DRCC_CTRL_POLICY_* (redundancy mode) */
    unsigned k;              /**< failed attempts for K_FAILED, 1..15 */
    int dual_tx;             /**< redundancy: every message on A, then on B */
    int star;                /**< redundancy: replicated star node (generation option) */
    drcc_chan_mode mode_a;   /**< channel A mode */
    drcc_chan_mode mode_b;   /**< channel B mode */
    int single_shot;         /**< no automatic retransmission (normal mode) */
    /** CTRL.busoff_manual (every mode, map 1.3): a channel that goes bus-off
     * stays bus-off until drcc_recover() allows its recovery. 0 = automatic
     * recovery after 128 x 11 recessive bits (ISO 11898-1). 1 on an instance
     * older than 1.3: drcc_configure() returns DRCC_E_UNSUPPORTED. */
    int busoff_manual;
    uint16_t recovery_bits;  /**< RMB_CFG.recovery_bits */
    uint16_t stall_limit;    /**< RMB_CFG.stall_limit, 0 = off */
    uint16_t dedup_window;   /**< DEDUP_CFG.window in bit times (0..32767), 0 = off */
    uint32_t int_enable;     /**< INT_ENABLE bits (DRCC_INT_ENABLE_*_MASK) */
    unsigned tx_queue_depth; /**< 0: SIZES' value; else must equal it */
    /* DMR mode only (written when mode == DRCC_MODE_DMR): */
    uint16_t dmr_timeout;        /**< DMR_CFG.timeout in ticks, not 0 */
    uint16_t dmr_cs_period;      /**< DMR_CFG.cs_period in ticks, 0 = none */
    uint16_t dmr_tick_bits;      /**< DMR_TIME.tick_bits, not 0 */
    uint16_t dmr_recovery_delay; /**< DMR_TIME.recovery_delay in ticks, not 0 */
    uint16_t dmr_cs_id_dcl;      /**< DMR_CS.cs_id_dcl (11 bits) */
    uint16_t dmr_cs_id_rcl;      /**< DMR_CS.cs_id_rcl (11 bits, != dcl) */
    /** CTRL.first_copy (map 1.4): deliver the first copy of each frame from
     * either line instead of the active line's only (DMR contract §8.1; needs
     * dedup_window). 1 on an instance older than 1.4: drcc_configure() returns
     * DRCC_E_UNSUPPORTED. */
    int dmr_first_copy;
} drcc_config;

/** A classical CAN frame as the registers carry it. */
typedef struct drcc_frame {
    uint32_t id;     /**< 11-bit (base) or 29-bit (extended) identifier, right-aligned */
    uint8_t ide;     /**< 1 = extended frame */
    uint8_t rtr;     /**< 1 = remote frame */
    uint8_t dlc;     /**< data length code 0..15 (min(dlc, 8) data bytes) */
    uint8_t channel; /**< received: 0 = channel A, 1 = B; ignored on send */
    uint8_t data[8]; /**< data bytes, byte 0 first on the bus */
    /** received: RX_TIME.rx_time, nominal bit times (16 bits, wrapping) when
     * the frame entered the RX FIFO; ignored on send */
    uint16_t timestamp;
} drcc_frame;

/** One channel's capture register (CAP_A / CAP_B), decoded. */
typedef struct drcc_capture {
    uint8_t err_valid; /**< an error was captured since the last re-arm */
    uint8_t err_kind;  /**< 1 bit, 2 stuff, 3 CRC, 4 form, 5 ACK (DRCC_ERR_*) */
    uint8_t err_field; /**< the frame field of the error (DRCC_FIELD_*) */
    uint8_t err_tx;    /**< 1: the channel was transmitting */
    uint8_t alc_valid; /**< an arbitration loss was captured since the last re-arm */
    uint8_t alc;       /**< lost bit: base id bit i (MSB first) i, SRR/RTR 11, IDE 12,
                            extension bit j 13 + j, extended RTR 31 */
} drcc_capture;

/** Error kinds of drcc_capture.err_kind. */
enum drcc_err_kind {
    DRCC_ERR_BIT = 1,
    DRCC_ERR_STUFF = 2,
    DRCC_ERR_CRC = 3,
    DRCC_ERR_FORM = 4,
    DRCC_ERR_ACK = 5
};

/** A few frame fields of drcc_capture.err_field (the channel's field codes). */
enum drcc_field {
    DRCC_FIELD_IDLE = 1,
    DRCC_FIELD_ID_A = 2,
    DRCC_FIELD_DATA = 10,
    DRCC_FIELD_CRC = 11,
    DRCC_FIELD_ACK_SLOT = 13,
    DRCC_FIELD_EOF = 15
};

/** What drcc_isr() did. */
typedef struct drcc_irq_result {
    uint32_t events;    /**< INT_STATUS as read and acknowledged (DRCC_INT_STATUS_*) */
    size_t frames;      /**< frames stored into the caller's buffer */
    int more;           /**< 1: the buffer filled up and the FIFO still holds frames */
    drcc_capture cap_a; /**< CAP_A before the acknowledgement re-armed it */
    drcc_capture cap_b; /**< CAP_B likewise */
} drcc_irq_result;

/** An acceptance filter: a frame passes if its format is `ide`, its identifier
 * agrees with `id` in every bit set in `mask`, and (if `match_rtr`) its remote
 * flag is `rtr`. */
typedef struct drcc_filter {
    uint32_t id;       /**< identifier (11 or 29 bits) */
    uint32_t mask;     /**< identifier bits compared, 1 = must match */
    uint8_t ide;       /**< 0: base frames only, 1: extended frames only */
    uint8_t rtr;       /**< the remote flag to match (with match_rtr) */
    uint8_t match_rtr; /**< 1: compare the remote flag too */
} drcc_filter;

/** One channel's fault confinement and validity. */
typedef struct drcc_chan_status {
    uint16_t tec;        /**< transmit error counter */
    uint8_t rec;         /**< receive error counter */
    uint8_t err_state;   /**< 0 error active, 1 error passive, 2 bus-off */
    uint8_t err_warning; /**< TEC or REC >= ewl */
    uint8_t aux_state;   /**< DRCC_AUX_* */
    uint8_t aux_causes;  /**< AUX_x bits [6:2] (passive, busoff, kfail, stall, warning) */
    uint8_t fail_cnt;    /**< failed attempts since the last success */
    uint8_t failures;    /**< times judged failed */
    uint8_t recoveries;  /**< times recovered */
} drcc_chan_status;

/** STATUS and the per-channel registers, decoded. */
typedef struct drcc_status {
    uint8_t state;       /**< main FSM state, DRCC_STATE_* */
    uint8_t tx_channel;  /**< 0 A, 1 B */
    uint8_t reset_mode;  /**< CTRL.reset_mode */
    uint8_t tx_going_on; /**< a transmission is in progress */
    uint8_t txq_a;       /**< frames in TX queue A */
    uint8_t txq_b;       /**< frames in TX queue B */
    uint8_t rx_count;    /**< frames in the RX FIFO */
    drcc_chan_status a;  /**< channel A */
    drcc_chan_status b;  /**< channel B */
} drcc_status;

/** Statistics registers, decoded (saturating; cleared by rst and drcc_clear_stats()). */
typedef struct drcc_stats {
    uint16_t duplicates;   /**< STATS0: duplicates dropped */
    uint16_t overruns;     /**< STATS0: frames lost to a full RX FIFO */
    uint16_t switches;     /**< STATS1: channel switches */
    uint16_t recoveries;   /**< STATS1: channel recoveries */
    uint16_t last_tx_time; /**< TIMES, bit times */
    uint16_t switch_time;  /**< TIMES, bit times */
    uint16_t omissions_a;  /**< OMISSIONS: frames only channel B delivered */
    uint16_t omissions_b;  /**< OMISSIONS: frames only channel A delivered */
    uint32_t dmr_status;   /**< DMR_STATUS, raw (DRCC_DMR_STATUS_* fields) */
    uint32_t dmr_cs_count; /**< DMR_CS_COUNT, raw */
    uint32_t dmr_rx_stats; /**< DMR_RX_STATS, raw */
} drcc_stats;

/** Computes a bit timing giving exactly `bitrate` from `clock_hz`: 8..25 tq
 * per bit, TSEG2 2..8 (ISO 11898-1's information processing time), TSEG1
 * 1..16 and at least 3 clocks, sample point as near 87.5 % as possible (ties:
 * the smaller prescaler), SJW = min(4, TSEG2). DRCC_E_NO_TIMING if none. */
int drcc_calc_bit_timing(uint32_t clock_hz, uint32_t bitrate, drcc_bit_timing *out);

/** The BTR word for `bt` and the error warning limit `ewl` (minus-one codes,
 * BRP split into brp and brp_ext). `bt` must pass drcc_bit_timing_valid(). */
uint32_t drcc_btr_encode(const drcc_bit_timing *bt, uint8_t ewl);

/** 1 if every field of `bt` is inside the register's range, else 0. */
int drcc_bit_timing_valid(const drcc_bit_timing *bt);

/** Fills `cfg` with the reset values: normal mode, 1 Mbit/s at 8 MHz timing
 * (BTR's reset value), policy error-passive, k 1, no interrupts enabled. */
void drcc_config_default(drcc_config *cfg);

/** Binds the hooks, checks the ID register (DRCC_E_NODEV if not a DRCC), reads
 * VERSION and SIZES into dev->ident (DRCC_E_VERSION unless major is 1) and
 * takes the TX queue depth from SIZES. Writes nothing. */
int drcc_init(drcc_dev *dev, drcc_read32_fn read32, drcc_write32_fn write32, void *ctx);

/** Enters reset mode (channels held in reset, TX queues and RX FIFO emptied). */
int drcc_enter_reset(drcc_dev *dev);

/** Enters reset mode, writes the whole configuration and leaves reset mode with
 * CTRL (the mode) in one write. DRCC_E_REFUSED if the controller did not take it
 * (then it stays in reset mode). */
int drcc_configure(drcc_dev *dev, const drcc_config *cfg);

/** Changes only the operating mode (through reset mode, so the queues and the
 * FIFO are emptied), keeping the rest of the configuration. */
int drcc_set_mode(drcc_dev *dev, drcc_mode mode);

/** DMR mode: configures mailbox `index` (0..15); call in reset mode (after
 * drcc_enter_reset(), before drcc_configure() with DRCC_MODE_DMR, which keeps
 * mailboxes). `dir` 0 receive, 1 transmit; `mask` 1 bits must match; `limit`
 * 1..127. DRCC_E_REFUSED on a top without mailboxes. */
int drcc_dmr_mailbox(drcc_dev *dev, unsigned index, uint32_t id, int ide, int dir,
                     uint32_t mask, unsigned limit);

/** Queues `frame` for sending: `queue` 0 (channel A) or 1 (B) in normal mode,
 * ignored otherwise. DRCC_E_FULL when the queue is full, DRCC_E_STATE in reset
 * mode, DRCC_E_INVAL for an identifier or DLC out of range. */
int drcc_send(drcc_dev *dev, const drcc_frame *frame, unsigned queue);

/** Transmit abort (TX_CMD.abort_a / abort_b, contract §11.5) of the queues in
 * `channels` (DRCC_CH_A, DRCC_CH_B or DRCC_CH_BOTH: one write, both at the same
 * clock).
 * - Normal mode: the queue's frames that no channel holds yet are dropped (no
 *   event); the frame the channel holds is aborted as the SJA1000's CMR.AT
 *   does: dropped at once if it is not on the bus, else the attempt in
 *   progress ends (a success stays a success) and is not retried. Either way
 *   that frame ends with INT_STATUS.tx_done or tx_failure and the channel's
 *   tx_done_a/b or tx_failure_a/b, and the queue count drops to 0.
 * - Redundancy mode: one logical queue; any non-empty `channels` aborts it
 *   (abort_a). Its head, the message the redundancy manager holds, is kept
 *   and ends as every message does (sent once, or failed); the messages behind
 *   it are dropped.
 * - DMR mode: the hardware refuses an abort (CiA 701: every message goes on
 *   both lines); the driver returns DRCC_E_STATE and writes nothing.
 * - Reset mode: the queues are empty; the write does nothing.
 * DRCC_E_INVAL for an empty or unknown `channels`, DRCC_E_UNSUPPORTED below
 * map 1.2 (nothing written). */
int drcc_abort(drcc_dev *dev, unsigned channels);

/** Manual bus-off recovery (TX_CMD.recover_a / recover_b, contract §11.6):
 * allows the channels in `channels` (DRCC_CH_A, DRCC_CH_B, DRCC_CH_BOTH), when
 * bus-off and held by drcc_config.busoff_manual, to start their recovery:
 * 128 x 11 recessive bits from the write on (never shorter), then error
 * active (err_state 0, INT_STATUS.err_state), and the frame the channel held
 * is sent. The permission is taken only from a bus-off channel: call it once
 * the channel is bus-off (INT_STATUS.err_state, drcc_get_status()); for a
 * channel that is not bus-off, or without busoff_manual, the write does
 * nothing. Every mode. DRCC_E_INVAL for an empty or unknown `channels`,
 * DRCC_E_UNSUPPORTED below map 1.3 (nothing written). */
int drcc_recover(drcc_dev *dev, unsigned channels);

/** Takes the head of the RX FIFO into `frame`, with its timestamp;
 * DRCC_E_EMPTY if there is none. */
int drcc_receive(drcc_dev *dev, drcc_frame *frame);

/** RX_TIME.now: nominal bit times since reset mode was left (16 bits,
 * wrapping); a frame's age is (uint16_t)(drcc_now() - frame.timestamp). */
uint16_t drcc_now(drcc_dev *dev);

/** The interrupt handler: reads INT_STATUS; if bus_error or arb_lost is set,
 * reads CAP_A and CAP_B; acknowledges INT_STATUS (W1C, which also re-arms the
 * captures), then drains the RX FIFO into `buf` (at most `cap` frames). Loses
 * no event: a frame arriving during the drain raises INT_STATUS.rx again. */
drcc_irq_result drcc_isr(drcc_dev *dev, drcc_frame *buf, size_t cap);

/** Sets acceptance filter `index` (0 or 1) and enables it; `f` NULL disables
 * it. Filters are configuration: called outside reset mode, it enters reset
 * mode (emptying the queues and the FIFO), writes and leaves it with the
 * configuration kept; called in reset mode, it stays there. With no filter
 * enabled every frame is accepted. */
int drcc_set_filter(drcc_dev *dev, unsigned index, const drcc_filter *f);
/** Disables both filters (every frame accepted), as drcc_set_filter(). */
int drcc_clear_filters(drcc_dev *dev);

/** Decodes a CAP_A / CAP_B word. */
drcc_capture drcc_decode_capture(uint32_t word);
/** Reads CAP_A and CAP_B (either pointer may be NULL); no side effect. */
void drcc_get_captures(drcc_dev *dev, drcc_capture *a, drcc_capture *b);
/** Re-arms the captures: clears INT_STATUS.bus_error (if `errors`) and
 * INT_STATUS.arb_lost (if `arb`), which clears err_valid / alc_valid of both. */
void drcc_rearm_captures(drcc_dev *dev, int errors, int arb);

/** Sets INT_ENABLE. */
void drcc_irq_enable(drcc_dev *dev, uint32_t mask);
/** Reads INT_STATUS. */
uint32_t drcc_irq_status(drcc_dev *dev);
/** Clears the INT_STATUS bits of `mask` (write 1 to clear). */
void drcc_irq_ack(drcc_dev *dev, uint32_t mask);

/** Reads STATUS, CHAN_A_ERR, CHAN_B_ERR, AUX_A and AUX_B. */
void drcc_get_status(drcc_dev *dev, drcc_status *st);
/** Reads STATS0, STATS1, TIMES, OMISSIONS and the DMR statistics. */
void drcc_get_stats(drcc_dev *dev, drcc_stats *stats);
/** STATS_CLR: clears STATS0, STATS1, OMISSIONS, DMR_RX_STATS and the AUX
 * failures/recoveries counts (TIMES and the error counters stay). */
void drcc_clear_stats(drcc_dev *dev);

#ifdef __cplusplus
}
#endif

#endif /* DRCC_DRIVER_H */
