/* SPDX-License-Identifier: Apache-2.0 */
/* drcc.c: the portable C99 DRCC driver (see drcc.h): bit timing, bring-up,
 * identification, modes, filters, send, transmit abort, manual bus-off
 * recovery, the interrupt handler's receive path with timestamps and
 * captures, status and statistics.
 * Every register access goes through the user's read32/write32 hooks; every
 * offset and field comes from the generated rtl-out/drcc_regs.h. */
#include "drcc.h"

/* Field helpers on the header's NAME_SHIFT / NAME_MASK pairs. */
#define FIELD_PUT(name, v) ((((uint32_t)(v)) << name##_SHIFT) & name##_MASK)
#define FIELD_GET(name, w) ((((uint32_t)(w)) & name##_MASK) >> name##_SHIFT)

/* BRP is 10 bits: brp holds [5:0], brp_ext [9:6]. */
#define BRP_LOW_BITS 6u
#define BRP_MAX 1024u
#define TQ_MIN 8u
#define TQ_MAX 25u
#define TSEG1_MAX 16u
#define TSEG2_MIN 2u
#define TSEG2_MAX 8u
#define SJW_MAX 4u

static uint32_t rd(drcc_dev *dev, uint32_t off) { return dev->read32(dev->ctx, off); }

static void wr(drcc_dev *dev, uint32_t off, uint32_t v) { dev->write32(dev->ctx, off, v); }

int drcc_calc_bit_timing(uint32_t clock_hz, uint32_t bitrate, drcc_bit_timing *out)
{
    uint32_t clocks, p;
    int found = 0;
    /* Best so far: sample-point error |8 (1 + tseg1) - 7 n| / (8 n), compared
     * by cross-multiplication as best_err / best_n. */
    uint32_t best_err = 0, best_n = 1;
    drcc_bit_timing best = {0, 0, 0, 0, 0};

    if (out == NULL || bitrate == 0u || clock_hz == 0u || clock_hz % bitrate != 0u) {
        return DRCC_E_NO_TIMING;
    }
    clocks = clock_hz / bitrate;
    for (p = 1u; p <= BRP_MAX && p <= clocks; p++) {
        uint32_t n, t2;
        if (clocks % p != 0u) {
            continue;
        }
        n = clocks / p;
        if (n < TQ_MIN || n > TQ_MAX) {
            continue;
        }
        for (t2 = TSEG2_MIN; t2 <= TSEG2_MAX; t2++) {
            uint32_t t1, sp8, err;
            if (n < 1u + t2 + 1u) {
                break;
            }
            t1 = n - 1u - t2;
            if (t1 > TSEG1_MAX || t1 * p < 3u) {
                continue;
            }
            sp8 = 8u * (1u + t1);
            err = sp8 > 7u * n ? sp8 - 7u * n : 7u * n - sp8;
            if (!found || err * best_n < best_err * n) {
                found = 1;
                best_err = err;
                best_n = n;
                best.brp = (uint16_t)p;
                best.tseg1 = (uint8_t)t1;
                best.tseg2 = (uint8_t)t2;
                best.sjw = (uint8_t)(t2 < SJW_MAX ? t2 : SJW_MAX);
                best.triple = 0;
            }
        }
    }
    if (!found) {
        return DRCC_E_NO_TIMING;
    }
    *out = best;
    return DRCC_OK;
}

int drcc_bit_timing_valid(const drcc_bit_timing *bt)
{
    return bt != NULL && bt->brp >= 1u && bt->brp <= BRP_MAX && bt->tseg1 >= 1u &&
           bt->tseg1 <= TSEG1_MAX && bt->tseg2 >= 1u && bt->tseg2 <= TSEG2_MAX &&
           bt->sjw >= 1u && bt->sjw <= SJW_MAX && bt->triple <= 1u;
}

uint32_t drcc_btr_encode(const drcc_bit_timing *bt, uint8_t ewl)
{
    uint32_t brp = (uint32_t)bt->brp - 1u;
    return FIELD_PUT(DRCC_BTR_BRP, brp & ((1u << BRP_LOW_BITS) - 1u)) |
           FIELD_PUT(DRCC_BTR_BRP_EXT, brp >> BRP_LOW_BITS) |
           FIELD_PUT(DRCC_BTR_TSEG1, bt->tseg1 - 1u) | FIELD_PUT(DRCC_BTR_TSEG2, bt->tseg2 - 1u) |
           FIELD_PUT(DRCC_BTR_SJW, bt->sjw - 1u) | FIELD_PUT(DRCC_BTR_TRIPLE, bt->triple) |
           FIELD_PUT(DRCC_BTR_EWL, ewl);
}

void drcc_config_default(drcc_config *cfg)
{
    /* BTR's reset value 0x00600500: brp 0, tseg1 4, tseg2 1, sjw 0, ewl 96. */
    cfg->timing.brp = 1;
    cfg->timing.tseg1 = 5;
    cfg->timing.tseg2 = 2;
    cfg->timing.sjw = 1;
    cfg->timing.triple = 0;
    cfg->ewl = 96;
    cfg->mode = DRCC_MODE_NORMAL;
    cfg->policy = DRCC_CTRL_POLICY_ERROR_PASSIVE;
    cfg->k = 1;
    cfg->dual_tx = 0;
    cfg->star = 0;
    cfg->mode_a = DRCC_CHAN_NORMAL;
    cfg->mode_b = DRCC_CHAN_NORMAL;
    cfg->single_shot = 0;
    cfg->busoff_manual = 0;
    cfg->dmr_first_copy = 0;
    cfg->recovery_bits = (uint16_t)FIELD_GET(DRCC_RMB_CFG_RECOVERY_BITS, DRCC_RMB_CFG_RESET);
    cfg->stall_limit = (uint16_t)FIELD_GET(DRCC_RMB_CFG_STALL_LIMIT, DRCC_RMB_CFG_RESET);
    cfg->dedup_window = (uint16_t)FIELD_GET(DRCC_DEDUP_CFG_WINDOW, DRCC_DEDUP_CFG_RESET);
    cfg->int_enable = 0;
    cfg->tx_queue_depth = 0;
    cfg->dmr_timeout = (uint16_t)FIELD_GET(DRCC_DMR_CFG_TIMEOUT, DRCC_DMR_CFG_RESET);
    cfg->dmr_cs_period = (uint16_t)FIELD_GET(DRCC_DMR_CFG_CS_PERIOD, DRCC_DMR_CFG_RESET);
    cfg->dmr_tick_bits = (uint16_t)FIELD_GET(DRCC_DMR_TIME_TICK_BITS, DRCC_DMR_TIME_RESET);
    cfg->dmr_recovery_delay =
        (uint16_t)FIELD_GET(DRCC_DMR_TIME_RECOVERY_DELAY, DRCC_DMR_TIME_RESET);
    cfg->dmr_cs_id_dcl = (uint16_t)FIELD_GET(DRCC_DMR_CS_CS_ID_DCL, DRCC_DMR_CS_RESET);
    cfg->dmr_cs_id_rcl = (uint16_t)FIELD_GET(DRCC_DMR_CS_CS_ID_RCL, DRCC_DMR_CS_RESET);
}

int drcc_init(drcc_dev *dev, drcc_read32_fn read32, drcc_write32_fn write32, void *ctx)
{
    uint32_t version, sizes;
    if (dev == NULL || read32 == NULL || write32 == NULL) {
        return DRCC_E_INVAL;
    }
    dev->read32 = read32;
    dev->write32 = write32;
    dev->ctx = ctx;
    if (rd(dev, DRCC_ID_OFFSET) != DRCC_ID_VALUE) {
        return DRCC_E_NODEV;
    }
    version = rd(dev, DRCC_VERSION_OFFSET);
    sizes = rd(dev, DRCC_SIZES_OFFSET);
    dev->ident.major = (uint8_t)FIELD_GET(DRCC_VERSION_MAJOR, version);
    dev->ident.minor = (uint8_t)FIELD_GET(DRCC_VERSION_MINOR, version);
    dev->ident.rx_fifo_depth = (uint8_t)FIELD_GET(DRCC_SIZES_RX_FIFO_DEPTH, sizes);
    dev->ident.tx_queue_depth = (uint8_t)FIELD_GET(DRCC_SIZES_TX_QUEUE_DEPTH, sizes);
    dev->ident.history = (uint8_t)FIELD_GET(DRCC_SIZES_HISTORY, sizes);
    dev->ident.mailboxes = (uint8_t)FIELD_GET(DRCC_SIZES_MAILBOXES, sizes);
    dev->ident.dmr = (uint8_t)FIELD_GET(DRCC_SIZES_DMR, sizes);
    dev->ident.star = (uint8_t)FIELD_GET(DRCC_SIZES_STAR, sizes);
    /* Major 0 is the map before VERSION existed (0x98 reads 0). */
    if (dev->ident.major != 1u) {
        return DRCC_E_VERSION;
    }
    dev->tx_queue_depth = dev->ident.tx_queue_depth;
    dev->ctrl = rd(dev, DRCC_CTRL_OFFSET) & ~DRCC_CTRL_RESET_MODE_MASK;
    return DRCC_OK;
}

int drcc_enter_reset(drcc_dev *dev)
{
    /* Outside reset mode only reset_mode is taken, and a CTRL write whose cfg
     * fields differ is flagged illegal: write back what CTRL holds. */
    uint32_t ctrl = rd(dev, DRCC_CTRL_OFFSET);
    wr(dev, DRCC_CTRL_OFFSET, ctrl | DRCC_CTRL_RESET_MODE_MASK);
    if (!FIELD_GET(DRCC_STATUS_RESET_MODE, rd(dev, DRCC_STATUS_OFFSET))) {
        return DRCC_E_REFUSED;
    }
    return DRCC_OK;
}

/* The CTRL word of `cfg` with reset_mode 0, or 0xFFFFFFFF if a field is out of range. */
static uint32_t ctrl_word(const drcc_config *cfg)
{
    unsigned k = cfg->k == 0u ? 1u : cfg->k; /* the hardware stores 0 as 1 */
    if (cfg->mode > DRCC_MODE_DMR || cfg->policy > DRCC_CTRL_POLICY_WARNING || k > 15u ||
        cfg->mode_a > DRCC_CHAN_LOOPBACK || cfg->mode_b > DRCC_CHAN_LOOPBACK) {
        return 0xFFFFFFFFu;
    }
    return FIELD_PUT(DRCC_CTRL_REDUNDANCY, cfg->mode == DRCC_MODE_REDUNDANCY) |
           FIELD_PUT(DRCC_CTRL_DMR, cfg->mode == DRCC_MODE_DMR) |
           FIELD_PUT(DRCC_CTRL_POLICY, cfg->policy) | FIELD_PUT(DRCC_CTRL_DUAL_TX, cfg->dual_tx != 0) |
           FIELD_PUT(DRCC_CTRL_STAR, cfg->star != 0) | FIELD_PUT(DRCC_CTRL_K, k) |
           FIELD_PUT(DRCC_CTRL_MODE_A, cfg->mode_a) | FIELD_PUT(DRCC_CTRL_MODE_B, cfg->mode_b) |
           FIELD_PUT(DRCC_CTRL_SINGLE_SHOT, cfg->single_shot != 0) |
           FIELD_PUT(DRCC_CTRL_BUSOFF_MANUAL, cfg->busoff_manual != 0) |
           FIELD_PUT(DRCC_CTRL_FIRST_COPY, cfg->mode == DRCC_MODE_DMR && cfg->dmr_first_copy != 0);
}

/* Writes `value` to a configuration register and checks it was taken. */
static int write_checked(drcc_dev *dev, uint32_t off, uint32_t value)
{
    wr(dev, off, value);
    return rd(dev, off) == value ? DRCC_OK : DRCC_E_REFUSED;
}

/* Writes CTRL with reset_mode 0 and checks it was taken (else reset mode stays). */
static int start(drcc_dev *dev, uint32_t ctrl)
{
    wr(dev, DRCC_CTRL_OFFSET, ctrl);
    if (rd(dev, DRCC_CTRL_OFFSET) != ctrl) {
        return DRCC_E_REFUSED;
    }
    dev->ctrl = ctrl;
    return DRCC_OK;
}

int drcc_configure(drcc_dev *dev, const drcc_config *cfg)
{
    uint32_t ctrl;
    int rc;

    if (cfg == NULL || !drcc_bit_timing_valid(&cfg->timing) || cfg->dedup_window > 0x7FFFu ||
        (cfg->tx_queue_depth != 0u && cfg->tx_queue_depth != dev->ident.tx_queue_depth)) {
        return DRCC_E_INVAL;
    }
    ctrl = ctrl_word(cfg);
    if (ctrl == 0xFFFFFFFFu) {
        return DRCC_E_INVAL;
    }
    if (cfg->busoff_manual && dev->ident.minor < DRCC_MINOR_BUSOFF_MANUAL) {
        return DRCC_E_UNSUPPORTED;
    }
    if ((ctrl & DRCC_CTRL_FIRST_COPY_MASK) != 0u && dev->ident.minor < DRCC_MINOR_FIRST_COPY) {
        return DRCC_E_UNSUPPORTED;
    }
    rc = drcc_enter_reset(dev);
    if (rc != DRCC_OK) {
        return rc;
    }
    rc = write_checked(dev, DRCC_BTR_OFFSET, drcc_btr_encode(&cfg->timing, cfg->ewl));
    if (rc == DRCC_OK) {
        rc = write_checked(dev, DRCC_RMB_CFG_OFFSET,
                           FIELD_PUT(DRCC_RMB_CFG_RECOVERY_BITS, cfg->recovery_bits) |
                               FIELD_PUT(DRCC_RMB_CFG_STALL_LIMIT, cfg->stall_limit));
    }
    if (rc == DRCC_OK) {
        rc = write_checked(dev, DRCC_DEDUP_CFG_OFFSET,
                           FIELD_PUT(DRCC_DEDUP_CFG_WINDOW, cfg->dedup_window));
    }
    if (rc == DRCC_OK && cfg->mode == DRCC_MODE_DMR) {
        if (cfg->dmr_timeout == 0u || cfg->dmr_tick_bits == 0u || cfg->dmr_recovery_delay == 0u ||
            cfg->dmr_cs_id_dcl > 0x7FFu || cfg->dmr_cs_id_rcl > 0x7FFu ||
            cfg->dmr_cs_id_dcl == cfg->dmr_cs_id_rcl) {
            return DRCC_E_INVAL;
        }
        rc = write_checked(dev, DRCC_DMR_CFG_OFFSET,
                           FIELD_PUT(DRCC_DMR_CFG_TIMEOUT, cfg->dmr_timeout) |
                               FIELD_PUT(DRCC_DMR_CFG_CS_PERIOD, cfg->dmr_cs_period));
        if (rc == DRCC_OK) {
            rc = write_checked(dev, DRCC_DMR_TIME_OFFSET,
                               FIELD_PUT(DRCC_DMR_TIME_TICK_BITS, cfg->dmr_tick_bits) |
                                   FIELD_PUT(DRCC_DMR_TIME_RECOVERY_DELAY, cfg->dmr_recovery_delay));
        }
        if (rc == DRCC_OK) {
            uint32_t cs = FIELD_PUT(DRCC_DMR_CS_CS_ID_DCL, cfg->dmr_cs_id_dcl) |
                          FIELD_PUT(DRCC_DMR_CS_CS_ID_RCL, cfg->dmr_cs_id_rcl);
            /* Refused while a mailbox is enabled: skip an unchanged value. */
            if (rd(dev, DRCC_DMR_CS_OFFSET) != cs) {
                rc = write_checked(dev, DRCC_DMR_CS_OFFSET, cs);
            }
        }
    }
    if (rc != DRCC_OK) {
        return rc;
    }
    wr(dev, DRCC_INT_ENABLE_OFFSET, cfg->int_enable);
    return start(dev, ctrl);
}

int drcc_set_mode(drcc_dev *dev, drcc_mode mode)
{
    uint32_t ctrl;
    int rc;
    if (mode > DRCC_MODE_DMR) {
        return DRCC_E_INVAL;
    }
    ctrl = dev->ctrl & ~(DRCC_CTRL_REDUNDANCY_MASK | DRCC_CTRL_DMR_MASK | DRCC_CTRL_RESET_MODE_MASK);
    ctrl |= FIELD_PUT(DRCC_CTRL_REDUNDANCY, mode == DRCC_MODE_REDUNDANCY) |
            FIELD_PUT(DRCC_CTRL_DMR, mode == DRCC_MODE_DMR);
    rc = drcc_enter_reset(dev);
    if (rc != DRCC_OK) {
        return rc;
    }
    return start(dev, ctrl);
}

int drcc_dmr_mailbox(drcc_dev *dev, unsigned index, uint32_t id, int ide, int dir,
                     uint32_t mask, unsigned limit)
{
    uint32_t id_word;
    int rc;
    if (index > DRCC_MB_SEL_INDEX_MASK || limit == 0u || limit > 127u ||
        id > (ide ? DRCC_MB_ID_ID_MASK : 0x7FFu) || mask > DRCC_MB_MASK_MASK_MASK) {
        return DRCC_E_INVAL;
    }
    if (!FIELD_GET(DRCC_STATUS_RESET_MODE, rd(dev, DRCC_STATUS_OFFSET))) {
        return DRCC_E_STATE;
    }
    id_word = FIELD_PUT(DRCC_MB_ID_ID, id) | FIELD_PUT(DRCC_MB_ID_IDE, ide != 0) |
              FIELD_PUT(DRCC_MB_ID_DIR, dir != 0);
    rc = write_checked(dev, DRCC_MB_SEL_OFFSET, FIELD_PUT(DRCC_MB_SEL_INDEX, index));
    if (rc == DRCC_OK) {
        rc = write_checked(dev, DRCC_MB_ID_OFFSET, id_word);
    }
    if (rc == DRCC_OK) {
        rc = write_checked(dev, DRCC_MB_MASK_OFFSET, FIELD_PUT(DRCC_MB_MASK_MASK, mask));
    }
    if (rc == DRCC_OK) {
        rc = write_checked(dev, DRCC_MB_CFG_OFFSET,
                           FIELD_PUT(DRCC_MB_CFG_LIMIT, limit) | DRCC_MB_CFG_ENABLE_MASK);
    }
    return rc;
}

static uint32_t data_word(const uint8_t *b) { return (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24; }

static void data_bytes(uint32_t w, uint8_t *b)
{
    b[0] = (uint8_t)w;
    b[1] = (uint8_t)(w >> 8);
    b[2] = (uint8_t)(w >> 16);
    b[3] = (uint8_t)(w >> 24);
}

int drcc_send(drcc_dev *dev, const drcc_frame *frame, unsigned queue)
{
    uint32_t status, count, id_max;
    uint8_t data[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    unsigned i, len;
    int normal = !(dev->ctrl & (DRCC_CTRL_REDUNDANCY_MASK | DRCC_CTRL_DMR_MASK));

    if (frame == NULL || queue > 1u || frame->dlc > DRCC_TX_CTRL_DLC_MASK) {
        return DRCC_E_INVAL;
    }
    id_max = frame->ide ? DRCC_TX_ID_ID_MASK : 0x7FFu;
    if (frame->id > id_max) {
        return DRCC_E_INVAL;
    }
    if (!normal) {
        queue = 0; /* redundancy and DMR modes use queue A only */
    }
    status = rd(dev, DRCC_STATUS_OFFSET);
    if (FIELD_GET(DRCC_STATUS_RESET_MODE, status)) {
        return DRCC_E_STATE;
    }
    count = queue ? FIELD_GET(DRCC_STATUS_TXQ_B_COUNT, status)
                  : FIELD_GET(DRCC_STATUS_TXQ_A_COUNT, status);
    if (count >= dev->tx_queue_depth) {
        return DRCC_E_FULL;
    }
    len = frame->rtr ? 0u : (frame->dlc < 8u ? frame->dlc : 8u);
    for (i = 0; i < len; i++) {
        data[i] = frame->data[i];
    }
    wr(dev, DRCC_TX_ID_OFFSET, FIELD_PUT(DRCC_TX_ID_ID, frame->id) |
                                   FIELD_PUT(DRCC_TX_ID_IDE, frame->ide != 0) |
                                   FIELD_PUT(DRCC_TX_ID_RTR, frame->rtr != 0));
    wr(dev, DRCC_TX_CTRL_OFFSET,
       FIELD_PUT(DRCC_TX_CTRL_DLC, frame->dlc) | FIELD_PUT(DRCC_TX_CTRL_QUEUE, queue));
    wr(dev, DRCC_TX_DATA0_OFFSET, data_word(&data[0]));
    wr(dev, DRCC_TX_DATA1_OFFSET, data_word(&data[4]));
    wr(dev, DRCC_TX_CMD_OFFSET, DRCC_TX_CMD_PUSH_MASK);
    return DRCC_OK;
}

/* The TX_CMD bits `a` / `b` of the channels in `channels`, or 0 if the set
 * is empty or has unknown bits. */
static uint32_t tx_cmd_bits(unsigned channels, uint32_t a, uint32_t b)
{
    if (channels == 0u || (channels & ~(unsigned)DRCC_CH_BOTH) != 0u) {
        return 0u;
    }
    return ((channels & (unsigned)DRCC_CH_A) ? a : 0u) | ((channels & (unsigned)DRCC_CH_B) ? b : 0u);
}

int drcc_abort(drcc_dev *dev, unsigned channels)
{
    uint32_t cmd = tx_cmd_bits(channels, DRCC_TX_CMD_ABORT_A_MASK, DRCC_TX_CMD_ABORT_B_MASK);
    if (cmd == 0u) {
        return DRCC_E_INVAL;
    }
    if (dev->ident.minor < DRCC_MINOR_ABORT) {
        return DRCC_E_UNSUPPORTED;
    }
    /* The hardware refuses an abort in DMR mode (illegal): do not write. */
    if (dev->ctrl & DRCC_CTRL_DMR_MASK) {
        return DRCC_E_STATE;
    }
    /* Redundancy mode: the one logical queue is queue A (abort_b is ignored). */
    if (dev->ctrl & DRCC_CTRL_REDUNDANCY_MASK) {
        cmd = DRCC_TX_CMD_ABORT_A_MASK;
    }
    wr(dev, DRCC_TX_CMD_OFFSET, cmd);
    return DRCC_OK;
}

int drcc_recover(drcc_dev *dev, unsigned channels)
{
    uint32_t cmd = tx_cmd_bits(channels, DRCC_TX_CMD_RECOVER_A_MASK, DRCC_TX_CMD_RECOVER_B_MASK);
    if (cmd == 0u) {
        return DRCC_E_INVAL;
    }
    if (dev->ident.minor < DRCC_MINOR_BUSOFF_MANUAL) {
        return DRCC_E_UNSUPPORTED;
    }
    wr(dev, DRCC_TX_CMD_OFFSET, cmd);
    return DRCC_OK;
}

int drcc_receive(drcc_dev *dev, drcc_frame *frame)
{
    uint32_t id = rd(dev, DRCC_RX_ID_OFFSET);
    uint32_t ctrl;
    if (!FIELD_GET(DRCC_RX_ID_RX_READY, id)) {
        return DRCC_E_EMPTY;
    }
    /* RX_ID's other fields, RX_CTRL and RX_DATA* are valid while rx_ready. */
    ctrl = rd(dev, DRCC_RX_CTRL_OFFSET);
    frame->id = FIELD_GET(DRCC_RX_ID_ID, id);
    frame->ide = (uint8_t)FIELD_GET(DRCC_RX_ID_IDE, id);
    frame->rtr = (uint8_t)FIELD_GET(DRCC_RX_ID_RTR, id);
    frame->dlc = (uint8_t)FIELD_GET(DRCC_RX_CTRL_DLC, ctrl);
    frame->channel = (uint8_t)FIELD_GET(DRCC_RX_CTRL_CHANNEL, ctrl);
    data_bytes(rd(dev, DRCC_RX_DATA0_OFFSET), &frame->data[0]);
    data_bytes(rd(dev, DRCC_RX_DATA1_OFFSET), &frame->data[4]);
    frame->timestamp = (uint16_t)FIELD_GET(DRCC_RX_TIME_RX_TIME, rd(dev, DRCC_RX_TIME_OFFSET));
    wr(dev, DRCC_RX_CMD_OFFSET, DRCC_RX_CMD_POP_MASK);
    return DRCC_OK;
}

drcc_irq_result drcc_isr(drcc_dev *dev, drcc_frame *buf, size_t cap)
{
    drcc_irq_result r;
    r.events = rd(dev, DRCC_INT_STATUS_OFFSET);
    r.frames = 0;
    r.more = 0;
    r.cap_a = drcc_decode_capture(0);
    r.cap_b = r.cap_a;
    /* The acknowledgement re-arms the captures: read them before it. */
    if (r.events & (DRCC_INT_STATUS_BUS_ERROR_MASK | DRCC_INT_STATUS_ARB_LOST_MASK)) {
        drcc_get_captures(dev, &r.cap_a, &r.cap_b);
    }
    /* Acknowledge first, then drain: a frame arriving meanwhile sets rx again. */
    wr(dev, DRCC_INT_STATUS_OFFSET, r.events);
    while (r.frames < cap) {
        if (drcc_receive(dev, &buf[r.frames]) != DRCC_OK) {
            return r;
        }
        r.frames++;
    }
    r.more = FIELD_GET(DRCC_RX_ID_RX_READY, rd(dev, DRCC_RX_ID_OFFSET)) != 0u;
    return r;
}

void drcc_irq_enable(drcc_dev *dev, uint32_t mask) { wr(dev, DRCC_INT_ENABLE_OFFSET, mask); }

uint32_t drcc_irq_status(drcc_dev *dev) { return rd(dev, DRCC_INT_STATUS_OFFSET); }

void drcc_irq_ack(drcc_dev *dev, uint32_t mask) { wr(dev, DRCC_INT_STATUS_OFFSET, mask); }

/* AUX_A and AUX_B, CHAN_A_ERR and CHAN_B_ERR share one layout. */
static void chan_status(uint32_t err, uint32_t aux, drcc_chan_status *c)
{
    c->tec = (uint16_t)FIELD_GET(DRCC_CHAN_A_ERR_TEC, err);
    c->rec = (uint8_t)FIELD_GET(DRCC_CHAN_A_ERR_REC, err);
    c->err_state = (uint8_t)FIELD_GET(DRCC_CHAN_A_ERR_ERR_STATE, err);
    c->err_warning = (uint8_t)FIELD_GET(DRCC_CHAN_A_ERR_ERR_WARNING, err);
    c->aux_state = (uint8_t)FIELD_GET(DRCC_AUX_A_STATE, aux);
    c->aux_causes = (uint8_t)((aux & (DRCC_AUX_A_CAUSE_PASSIVE_MASK | DRCC_AUX_A_CAUSE_BUSOFF_MASK |
                                      DRCC_AUX_A_CAUSE_KFAIL_MASK | DRCC_AUX_A_CAUSE_STALL_MASK |
                                      DRCC_AUX_A_CAUSE_WARNING_MASK)) >>
                              DRCC_AUX_A_CAUSE_PASSIVE_SHIFT);
    c->fail_cnt = (uint8_t)FIELD_GET(DRCC_AUX_A_FAIL_CNT, aux);
    c->failures = (uint8_t)FIELD_GET(DRCC_AUX_A_FAILURES, aux);
    c->recoveries = (uint8_t)FIELD_GET(DRCC_AUX_A_RECOVERIES, aux);
}

void drcc_get_status(drcc_dev *dev, drcc_status *st)
{
    uint32_t s = rd(dev, DRCC_STATUS_OFFSET);
    st->state = (uint8_t)FIELD_GET(DRCC_STATUS_STATE, s);
    st->tx_channel = (uint8_t)FIELD_GET(DRCC_STATUS_TX_CHANNEL, s);
    st->reset_mode = (uint8_t)FIELD_GET(DRCC_STATUS_RESET_MODE, s);
    st->tx_going_on = (uint8_t)FIELD_GET(DRCC_STATUS_TX_GOING_ON, s);
    st->txq_a = (uint8_t)FIELD_GET(DRCC_STATUS_TXQ_A_COUNT, s);
    st->txq_b = (uint8_t)FIELD_GET(DRCC_STATUS_TXQ_B_COUNT, s);
    st->rx_count = (uint8_t)FIELD_GET(DRCC_STATUS_RX_COUNT, s);
    chan_status(rd(dev, DRCC_CHAN_A_ERR_OFFSET), rd(dev, DRCC_AUX_A_OFFSET), &st->a);
    chan_status(rd(dev, DRCC_CHAN_B_ERR_OFFSET), rd(dev, DRCC_AUX_B_OFFSET), &st->b);
}

void drcc_get_stats(drcc_dev *dev, drcc_stats *stats)
{
    uint32_t s0 = rd(dev, DRCC_STATS0_OFFSET);
    uint32_t s1 = rd(dev, DRCC_STATS1_OFFSET);
    uint32_t t = rd(dev, DRCC_TIMES_OFFSET);
    uint32_t o = rd(dev, DRCC_OMISSIONS_OFFSET);
    stats->duplicates = (uint16_t)FIELD_GET(DRCC_STATS0_DUPLICATES, s0);
    stats->overruns = (uint16_t)FIELD_GET(DRCC_STATS0_OVERRUNS, s0);
    stats->switches = (uint16_t)FIELD_GET(DRCC_STATS1_SWITCHES, s1);
    stats->recoveries = (uint16_t)FIELD_GET(DRCC_STATS1_RECOVERIES, s1);
    stats->last_tx_time = (uint16_t)FIELD_GET(DRCC_TIMES_LAST_TX_TIME, t);
    stats->switch_time = (uint16_t)FIELD_GET(DRCC_TIMES_SWITCH_TIME, t);
    stats->omissions_a = (uint16_t)FIELD_GET(DRCC_OMISSIONS_OMISSIONS_A, o);
    stats->omissions_b = (uint16_t)FIELD_GET(DRCC_OMISSIONS_OMISSIONS_B, o);
    stats->dmr_status = rd(dev, DRCC_DMR_STATUS_OFFSET);
    stats->dmr_cs_count = rd(dev, DRCC_DMR_CS_COUNT_OFFSET);
    stats->dmr_rx_stats = rd(dev, DRCC_DMR_RX_STATS_OFFSET);
}

void drcc_clear_stats(drcc_dev *dev) { wr(dev, DRCC_STATS_CLR_OFFSET, DRCC_STATS_CLR_CLEAR_MASK); }

uint16_t drcc_now(drcc_dev *dev)
{
    return (uint16_t)FIELD_GET(DRCC_RX_TIME_NOW, rd(dev, DRCC_RX_TIME_OFFSET));
}

drcc_capture drcc_decode_capture(uint32_t w)
{
    drcc_capture c;
    c.err_valid = (uint8_t)FIELD_GET(DRCC_CAP_A_ERR_VALID, w);
    c.err_kind = (uint8_t)FIELD_GET(DRCC_CAP_A_ERR_KIND, w);
    c.err_field = (uint8_t)FIELD_GET(DRCC_CAP_A_ERR_FIELD, w);
    c.err_tx = (uint8_t)FIELD_GET(DRCC_CAP_A_ERR_TX, w);
    c.alc_valid = (uint8_t)FIELD_GET(DRCC_CAP_A_ALC_VALID, w);
    c.alc = (uint8_t)FIELD_GET(DRCC_CAP_A_ALC, w);
    return c;
}

void drcc_get_captures(drcc_dev *dev, drcc_capture *a, drcc_capture *b)
{
    if (a != NULL) {
        *a = drcc_decode_capture(rd(dev, DRCC_CAP_A_OFFSET));
    }
    if (b != NULL) {
        *b = drcc_decode_capture(rd(dev, DRCC_CAP_B_OFFSET));
    }
}

void drcc_rearm_captures(drcc_dev *dev, int errors, int arb)
{
    uint32_t m = (errors ? DRCC_INT_STATUS_BUS_ERROR_MASK : 0u) |
                 (arb ? DRCC_INT_STATUS_ARB_LOST_MASK : 0u);
    if (m != 0u) {
        wr(dev, DRCC_INT_STATUS_OFFSET, m);
    }
}

/* Writes both words of filter `index` (FILT_ID1/FILT_MASK1 follow 8 bytes on). */
static int write_filter(drcc_dev *dev, unsigned index, uint32_t id, uint32_t mask)
{
    uint32_t step = index * (DRCC_FILT_ID1_OFFSET - DRCC_FILT_ID0_OFFSET);
    int rc = write_checked(dev, DRCC_FILT_ID0_OFFSET + step, id);
    return rc == DRCC_OK ? write_checked(dev, DRCC_FILT_MASK0_OFFSET + step, mask) : rc;
}

/* Writes the filter words of `ids`/`masks` for the filters in `which` (bit k =
 * filter k) in reset mode, leaving it again if the controller was running. */
static int write_filters(drcc_dev *dev, unsigned which, const uint32_t *ids, const uint32_t *masks)
{
    unsigned k;
    int rc = DRCC_OK;
    int running = !FIELD_GET(DRCC_STATUS_RESET_MODE, rd(dev, DRCC_STATUS_OFFSET));
    if (running) {
        rc = drcc_enter_reset(dev);
    }
    for (k = 0; k < 2u && rc == DRCC_OK; k++) {
        if (which & (1u << k)) {
            rc = write_filter(dev, k, ids[k], masks[k]);
        }
    }
    if (rc != DRCC_OK || !running) {
        return rc;
    }
    return start(dev, dev->ctrl);
}

int drcc_set_filter(drcc_dev *dev, unsigned index, const drcc_filter *f)
{
    uint32_t ids[2] = {0, 0}, masks[2] = {0, 0};
    if (index > 1u) {
        return DRCC_E_INVAL;
    }
    if (f != NULL) {
        uint32_t id_max = f->ide ? DRCC_FILT_ID0_ID_MASK : 0x7FFu;
        if (f->id > id_max || f->mask > id_max) {
            return DRCC_E_INVAL;
        }
        /* The ide mask bit is always set: a base filter never passes an
         * extended frame whose low 11 bits are equal, and vice versa. */
        ids[index] = FIELD_PUT(DRCC_FILT_ID0_ID, f->id) | FIELD_PUT(DRCC_FILT_ID0_IDE, f->ide != 0) |
                     FIELD_PUT(DRCC_FILT_ID0_RTR, f->rtr != 0);
        masks[index] = FIELD_PUT(DRCC_FILT_MASK0_ID, f->mask) | DRCC_FILT_MASK0_IDE_MASK |
                       FIELD_PUT(DRCC_FILT_MASK0_RTR, f->match_rtr != 0) |
                       DRCC_FILT_MASK0_ENABLE_MASK;
    }
    return write_filters(dev, 1u << index, ids, masks);
}

int drcc_clear_filters(drcc_dev *dev)
{
    static const uint32_t zero[2] = {0, 0};
    return write_filters(dev, 3u, zero, zero);
}
