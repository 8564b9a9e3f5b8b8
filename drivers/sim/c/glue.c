/* SPDX-License-Identifier: Apache-2.0 */
/* glue.c: what the Rust tests call the C driver through. The driver's own
 * structs (drcc_dev, drcc_config) stay on the C side; Rust sees an opaque
 * handle and plain arguments, plus drcc_frame / drcc_bit_timing /
 * drcc_irq_result, which it mirrors with #[repr(C)]. */
#include <stdlib.h>

#include "drcc.h"

/* A new driver bound to the hooks, after drcc_init(); NULL and *rc on error. */
drcc_dev *sim_c_open(drcc_read32_fn read32, drcc_write32_fn write32, void *ctx, int *rc)
{
    drcc_dev *dev = malloc(sizeof *dev);
    if (dev == NULL) {
        *rc = DRCC_E_INVAL;
        return NULL;
    }
    *rc = drcc_init(dev, read32, write32, ctx);
    if (*rc != DRCC_OK) {
        free(dev);
        return NULL;
    }
    return dev;
}

/* Frees a driver from sim_c_open(). */
void sim_c_close(drcc_dev *dev) { free(dev); }

/* drcc_configure() with the bit timing computed by drcc_calc_bit_timing() and
 * the parameters the tests vary; the rest stays at drcc_config_default(). */
int sim_c_configure(drcc_dev *dev, uint32_t clock_hz, uint32_t bitrate, int mode, unsigned policy,
                    unsigned k, int dual_tx, uint16_t stall_limit, uint16_t recovery_bits,
                    uint16_t dedup_window, uint32_t int_enable)
{
    drcc_config cfg;
    int rc;
    drcc_config_default(&cfg);
    rc = drcc_calc_bit_timing(clock_hz, bitrate, &cfg.timing);
    if (rc != DRCC_OK) {
        return rc;
    }
    cfg.mode = (drcc_mode)mode;
    cfg.policy = policy;
    cfg.k = k;
    cfg.dual_tx = dual_tx;
    cfg.stall_limit = stall_limit;
    cfg.recovery_bits = recovery_bits;
    cfg.dedup_window = dedup_window;
    cfg.int_enable = int_enable;
    return drcc_configure(dev, &cfg);
}

/* drcc_configure() in normal mode with single-shot transmission (no
 * automatic retransmission), the bit timing of drcc_calc_bit_timing(). */
int sim_c_configure_single_shot(drcc_dev *dev, uint32_t clock_hz, uint32_t bitrate,
                                uint32_t int_enable)
{
    drcc_config cfg;
    int rc;
    drcc_config_default(&cfg);
    rc = drcc_calc_bit_timing(clock_hz, bitrate, &cfg.timing);
    if (rc != DRCC_OK) {
        return rc;
    }
    cfg.single_shot = 1;
    cfg.int_enable = int_enable;
    return drcc_configure(dev, &cfg);
}

/* STATS0 duplicates and STATS1 switches through drcc_get_stats(). */
void sim_c_stats(drcc_dev *dev, uint32_t *duplicates, uint32_t *switches)
{
    drcc_stats s;
    drcc_get_stats(dev, &s);
    *duplicates = s.duplicates;
    *switches = s.switches;
}

/* drcc_get_stats() in full (the tests read overruns too). */
void sim_c_stats_all(drcc_dev *dev, drcc_stats *out) { drcc_get_stats(dev, out); }

/* VERSION and SIZES as drcc_init() read them. */
drcc_ident sim_c_ident(const drcc_dev *dev) { return dev->ident; }

/* drcc_set_filter() with the filter's fields as arguments (enable 0: NULL). */
int sim_c_set_filter(drcc_dev *dev, unsigned index, int enable, uint32_t id, uint32_t mask,
                     int ide)
{
    drcc_filter f;
    f.id = id;
    f.mask = mask;
    f.ide = (uint8_t)(ide != 0);
    f.rtr = 0;
    f.match_rtr = 0;
    return drcc_set_filter(dev, index, enable ? &f : NULL);
}

/* The README's example (drivers/c/README.md, section "Example"), compiled from
 * the README itself by build.rs. */
int can_start(drcc_dev *can, drcc_read32_fn rd, drcc_write32_fn wr, void *base);

/* A new driver brought up by the README example's can_start(); NULL and *rc
 * on error. */
drcc_dev *sim_c_example_open(drcc_read32_fn read32, drcc_write32_fn write32, void *ctx, int *rc)
{
    drcc_dev *dev = malloc(sizeof *dev);
    if (dev == NULL) {
        *rc = DRCC_E_INVAL;
        return NULL;
    }
    *rc = can_start(dev, read32, write32, ctx);
    if (*rc != DRCC_OK) {
        free(dev);
        return NULL;
    }
    return dev;
}

/* Fake register hooks for drcc_init(): ID reads "DRCC", VERSION the value
 * `ctx` points to, SIZES the default top's, everything else 0. */
static uint32_t fake_read(void *ctx, uint32_t off)
{
    if (off == DRCC_ID_OFFSET) {
        return DRCC_ID_VALUE;
    }
    if (off == DRCC_VERSION_OFFSET) {
        return *(const uint32_t *)ctx;
    }
    return off == DRCC_SIZES_OFFSET ? DRCC_SIZES_RESET : 0u;
}

static void fake_write(void *ctx, uint32_t off, uint32_t value)
{
    (void)ctx;
    (void)off;
    (void)value;
}

/* drcc_init() on a device whose VERSION reads `version`. */
int sim_c_init_with_version(uint32_t version)
{
    drcc_dev dev;
    return drcc_init(&dev, fake_read, fake_write, &version);
}

/* drcc_configure() in mode `mode` with CTRL.busoff_manual = `busoff_manual`,
 * the bit timing of drcc_calc_bit_timing(); the rest drcc_config_default(). */
int sim_c_configure_manual(drcc_dev *dev, uint32_t clock_hz, uint32_t bitrate, int mode,
                           int busoff_manual, uint32_t int_enable)
{
    drcc_config cfg;
    int rc;
    drcc_config_default(&cfg);
    rc = drcc_calc_bit_timing(clock_hz, bitrate, &cfg.timing);
    if (rc != DRCC_OK) {
        return rc;
    }
    cfg.mode = (drcc_mode)mode;
    cfg.busoff_manual = busoff_manual;
    cfg.int_enable = int_enable;
    return drcc_configure(dev, &cfg);
}

/* drcc_get_status(). */
void sim_c_status(drcc_dev *dev, drcc_status *out) { drcc_get_status(dev, out); }

/* Fake registers that count writes: ID "DRCC", VERSION and CTRL as given,
 * SIZES the default top's, everything else 0. */
typedef struct fake_counting {
    uint32_t version;
    uint32_t ctrl;
    unsigned writes;
    uint32_t last_offset;
    uint32_t last_value;
} fake_counting;

static uint32_t counting_read(void *ctx, uint32_t off)
{
    const fake_counting *f = (const fake_counting *)ctx;
    if (off == DRCC_ID_OFFSET) {
        return DRCC_ID_VALUE;
    }
    if (off == DRCC_VERSION_OFFSET) {
        return f->version;
    }
    if (off == DRCC_CTRL_OFFSET) {
        return f->ctrl;
    }
    return off == DRCC_SIZES_OFFSET ? DRCC_SIZES_RESET : 0u;
}

static void counting_write(void *ctx, uint32_t off, uint32_t value)
{
    fake_counting *f = (fake_counting *)ctx;
    f->writes++;
    f->last_offset = off;
    f->last_value = value;
}

/* On a device whose VERSION reads `version` and CTRL `ctrl`: what = 0
 * drcc_abort(channels), 1 drcc_recover(channels), 2 drcc_configure() with
 * busoff_manual = channels, 3 drcc_configure() in DMR mode with
 * dmr_first_copy = channels. Returns the result code; *writes = register
 * writes the call made, last[0] / last[1] the offset and value of the last. */
int sim_c_call_with_version(uint32_t version, uint32_t ctrl, int what, unsigned channels,
                            unsigned *writes, uint32_t last[2])
{
    drcc_dev dev;
    fake_counting f;
    int rc;
    f.version = version;
    f.ctrl = ctrl;
    f.writes = 0;
    f.last_offset = 0;
    f.last_value = 0;
    rc = drcc_init(&dev, counting_read, counting_write, &f);
    if (rc != DRCC_OK) {
        return rc;
    }
    f.writes = 0;
    if (what == 0) {
        rc = drcc_abort(&dev, channels);
    } else if (what == 1) {
        rc = drcc_recover(&dev, channels);
    } else {
        drcc_config cfg;
        drcc_config_default(&cfg);
        if (what == 2) {
            cfg.busoff_manual = (int)channels;
        } else {
            cfg.mode = DRCC_MODE_DMR;
            cfg.dmr_first_copy = (int)channels;
        }
        rc = drcc_configure(&dev, &cfg);
    }
    *writes = f.writes;
    last[0] = f.last_offset;
    last[1] = f.last_value;
    return rc;
}
