// SPDX-License-Identifier: MIT
// zline RotatingModel: a lit cube turning on a 240x240 ST7789 (or in the
// middle of a 320x240 ILI9341), rendered one row at a time: zline needs a
// 3,176-byte work buffer and no frame buffer, so it runs on an Arduino Mega
// 2560 (8 KB of RAM) as well as on 32-bit boards.
//
// Wiring (Mega 2560; on other boards use their SPI pins): SCK 52, MOSI 51,
// panel CS 53, DC 49, RESET 48 (or 0xff if not wired), VCC and backlight
// to 3.3 V, GND. 5 V boards need a level shifter on the panel's inputs.
#include <zline.h>
#include <zl_spi_panel.h>

#include "arduino_spi_bus.h"
#include "rotating_scene.h"

// Set to 1 for a 320x240 ILI9341 module instead of a 240x240 ST7789.
#define USE_ILI9341 0

static const ArduinoSpiPins pins = {53, 49, 48, 8000000UL};
static zl_panel_bus bus;
static zl_panel panel;          // the driver's state (its fields are private)
static zl_panel_config panel_cfg;
// zline's work buffer; zline wants it 8-byte aligned, which uint64_t is not on AVR
static uint64_t work[ROTATING_SCENE_WORK_WORDS] ROTATING_SCENE_ALIGN8;
static uint16_t frame_index;
static bool panel_ready;

static uint16_t panel_x()
{
    return (uint16_t)((panel_cfg.width - ROTATING_SCENE_W) / 2);
}

void setup()
{
    Serial.begin(115200);
#if USE_ILI9341
    panel_cfg = zl_panel_config_ili9341_320x240();
#else
    panel_cfg = zl_panel_config_st7789_240x240();
#endif
    arduino_spi_bus_begin(&bus, &pins);
    zl_status s = zl_panel_init(&panel, &panel_cfg, &bus);
    panel_ready = s == ZL_OK;
    if (!panel_ready) {
        Serial.print(F("zl_panel_init failed, zl_status "));
        Serial.println((int)s);
    }
}

void loop()
{
    if (!panel_ready)
        return;
    unsigned long start = millis();
    zl_status s = zl_panel_window(&panel, panel_x(), 0, ROTATING_SCENE_W, ROTATING_SCENE_H);
    int r = s == ZL_OK ? rotating_scene_render(frame_index, work, sizeof work, zl_panel_send_band, &panel) : s;
    s = zl_panel_finish(&panel);
    if (r != 0 || s != ZL_OK) {
        Serial.print(F("frame failed, zl_status "));
        Serial.println(r != 0 ? r : (int)s);
        panel_ready = false;
        return;
    }
    frame_index = (uint16_t)((frame_index + 1) % ROTATING_SCENE_FRAMES);
    Serial.print(F("frame ms: "));
    Serial.println(millis() - start);
}
