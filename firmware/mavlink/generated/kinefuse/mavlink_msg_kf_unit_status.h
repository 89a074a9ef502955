#pragma once
// MESSAGE KF_UNIT_STATUS PACKING

#include <stdint.h>

#define MAVLINK_MSG_ID_KF_UNIT_STATUS 52504

MAVPACKED(
typedef struct __mavlink_kf_unit_status_t {
 uint64_t time_boot_us; /*< [us] Unit clock, microseconds since boot.*/
 uint32_t firmware_version; /*<  Firmware version: major << 24 | minor << 16 | patch << 8 | FIRMWARE_VERSION_TYPE.*/
 uint32_t firmware_git_hash; /*<  First 32 bits of the firmware's git commit hash (0: unknown).*/
 uint32_t dialect_hash; /*<  KF_DIALECT_HASH of the MAVLink headers the firmware was built with (the host warns on mismatch).*/
 uint32_t samples; /*<  Sensor samples taken.*/
 uint32_t samples_dropped; /*<  Sensor samples lost on the unit (FIFO overrun, late read).*/
 uint32_t frames_dropped; /*<  Outgoing frames dropped because the transmit buffer was full.*/
 uint32_t rejected_samples; /*<  Samples rejected by the orientation filter.*/
 uint32_t crc_errors; /*<  Received frames with a bad CRC.*/
 uint32_t unknown_messages; /*<  Received frames with an unknown message id.*/
 uint32_t param_rejects; /*<  PARAM_SET requests rejected (unknown name, wrong type, out of range).*/
 float sensor_rate_requested; /*< [Hz] Requested sensor sample rate.*/
 float sensor_rate_achieved; /*< [Hz] Sensor sample rate achieved since the previous status, measured on the unit clock.*/
 float raw_rate_requested; /*< [Hz] Requested KF_RAW_SAMPLE stream rate (0: off).*/
 float raw_rate_achieved; /*< [Hz] KF_RAW_SAMPLE frames sent per second since the previous status.*/
 float orientation_rate_requested; /*< [Hz] Requested KF_ORIENTATION stream rate (0: off).*/
 float orientation_rate_achieved; /*< [Hz] KF_ORIENTATION frames sent per second since the previous status.*/
 uint16_t battery_voltage; /*< [mV] Battery voltage (UINT16_MAX: unknown).*/
 uint16_t cpu_load; /*< [d%] Processor load (0..1000).*/
 uint16_t status_flags; /*<  Status bits.*/
 int8_t battery_remaining; /*< [%] Remaining battery charge (-1: unknown).*/
 uint8_t unit_id; /*<  Unit id.*/
 uint8_t filter_id; /*<  Orientation estimator running.*/
 uint8_t numeric_format; /*<  Arithmetic of the estimators.*/
 uint8_t earth_frame; /*<  Earth frame of KF_ORIENTATION.*/
 uint32_t numeric_resets; /*<  Orientation filter restarts after a non-finite state (either sensor's filter in two-sensor mode; each also sets NUMERIC_RESET in KF_ORIENTATION or KF_JOINT_ANGLE).*/
 uint32_t hil_invalid; /*<  HIL_SENSOR messages not processed: a NaN acc/gyro/mag value, or a sensor id the unit does not have (id 1 without two-sensor mode, id > 1).*/
 uint32_t rejected_samples2; /*<  Samples rejected by sensor 1's orientation filter (two-sensor mode, KF_JOINT_ID != 0; rejected_samples is sensor 0's).*/
}) mavlink_kf_unit_status_t;

#define MAVLINK_MSG_ID_KF_UNIT_STATUS_LEN 95
#define MAVLINK_MSG_ID_KF_UNIT_STATUS_MIN_LEN 83
#define MAVLINK_MSG_ID_52504_LEN 95
#define MAVLINK_MSG_ID_52504_MIN_LEN 83

#define MAVLINK_MSG_ID_KF_UNIT_STATUS_CRC 185
#define MAVLINK_MSG_ID_52504_CRC 185



#if MAVLINK_COMMAND_24BIT
#define MAVLINK_MESSAGE_INFO_KF_UNIT_STATUS { \
    52504, \
    "KF_UNIT_STATUS", \
    28, \
    {  { "time_boot_us", NULL, MAVLINK_TYPE_UINT64_T, 0, 0, offsetof(mavlink_kf_unit_status_t, time_boot_us) }, \
         { "firmware_version", NULL, MAVLINK_TYPE_UINT32_T, 0, 8, offsetof(mavlink_kf_unit_status_t, firmware_version) }, \
         { "firmware_git_hash", NULL, MAVLINK_TYPE_UINT32_T, 0, 12, offsetof(mavlink_kf_unit_status_t, firmware_git_hash) }, \
         { "dialect_hash", NULL, MAVLINK_TYPE_UINT32_T, 0, 16, offsetof(mavlink_kf_unit_status_t, dialect_hash) }, \
         { "samples", NULL, MAVLINK_TYPE_UINT32_T, 0, 20, offsetof(mavlink_kf_unit_status_t, samples) }, \
         { "samples_dropped", NULL, MAVLINK_TYPE_UINT32_T, 0, 24, offsetof(mavlink_kf_unit_status_t, samples_dropped) }, \
         { "frames_dropped", NULL, MAVLINK_TYPE_UINT32_T, 0, 28, offsetof(mavlink_kf_unit_status_t, frames_dropped) }, \
         { "rejected_samples", NULL, MAVLINK_TYPE_UINT32_T, 0, 32, offsetof(mavlink_kf_unit_status_t, rejected_samples) }, \
         { "crc_errors", NULL, MAVLINK_TYPE_UINT32_T, 0, 36, offsetof(mavlink_kf_unit_status_t, crc_errors) }, \
         { "unknown_messages", NULL, MAVLINK_TYPE_UINT32_T, 0, 40, offsetof(mavlink_kf_unit_status_t, unknown_messages) }, \
         { "param_rejects", NULL, MAVLINK_TYPE_UINT32_T, 0, 44, offsetof(mavlink_kf_unit_status_t, param_rejects) }, \
         { "sensor_rate_requested", NULL, MAVLINK_TYPE_FLOAT, 0, 48, offsetof(mavlink_kf_unit_status_t, sensor_rate_requested) }, \
         { "sensor_rate_achieved", NULL, MAVLINK_TYPE_FLOAT, 0, 52, offsetof(mavlink_kf_unit_status_t, sensor_rate_achieved) }, \
         { "raw_rate_requested", NULL, MAVLINK_TYPE_FLOAT, 0, 56, offsetof(mavlink_kf_unit_status_t, raw_rate_requested) }, \
         { "raw_rate_achieved", NULL, MAVLINK_TYPE_FLOAT, 0, 60, offsetof(mavlink_kf_unit_status_t, raw_rate_achieved) }, \
         { "orientation_rate_requested", NULL, MAVLINK_TYPE_FLOAT, 0, 64, offsetof(mavlink_kf_unit_status_t, orientation_rate_requested) }, \
         { "orientation_rate_achieved", NULL, MAVLINK_TYPE_FLOAT, 0, 68, offsetof(mavlink_kf_unit_status_t, orientation_rate_achieved) }, \
         { "battery_voltage", NULL, MAVLINK_TYPE_UINT16_T, 0, 72, offsetof(mavlink_kf_unit_status_t, battery_voltage) }, \
         { "cpu_load", NULL, MAVLINK_TYPE_UINT16_T, 0, 74, offsetof(mavlink_kf_unit_status_t, cpu_load) }, \
         { "status_flags", NULL, MAVLINK_TYPE_UINT16_T, 0, 76, offsetof(mavlink_kf_unit_status_t, status_flags) }, \
         { "battery_remaining", NULL, MAVLINK_TYPE_INT8_T, 0, 78, offsetof(mavlink_kf_unit_status_t, battery_remaining) }, \
         { "unit_id", NULL, MAVLINK_TYPE_UINT8_T, 0, 79, offsetof(mavlink_kf_unit_status_t, unit_id) }, \
         { "filter_id", NULL, MAVLINK_TYPE_UINT8_T, 0, 80, offsetof(mavlink_kf_unit_status_t, filter_id) }, \
         { "numeric_format", NULL, MAVLINK_TYPE_UINT8_T, 0, 81, offsetof(mavlink_kf_unit_status_t, numeric_format) }, \
         { "earth_frame", NULL, MAVLINK_TYPE_UINT8_T, 0, 82, offsetof(mavlink_kf_unit_status_t, earth_frame) }, \
         { "numeric_resets", NULL, MAVLINK_TYPE_UINT32_T, 0, 83, offsetof(mavlink_kf_unit_status_t, numeric_resets) }, \
         { "hil_invalid", NULL, MAVLINK_TYPE_UINT32_T, 0, 87, offsetof(mavlink_kf_unit_status_t, hil_invalid) }, \
         { "rejected_samples2", NULL, MAVLINK_TYPE_UINT32_T, 0, 91, offsetof(mavlink_kf_unit_status_t, rejected_samples2) }, \
         } \
}
#else
#define MAVLINK_MESSAGE_INFO_KF_UNIT_STATUS { \
    "KF_UNIT_STATUS", \
    28, \
    {  { "time_boot_us", NULL, MAVLINK_TYPE_UINT64_T, 0, 0, offsetof(mavlink_kf_unit_status_t, time_boot_us) }, \
         { "firmware_version", NULL, MAVLINK_TYPE_UINT32_T, 0, 8, offsetof(mavlink_kf_unit_status_t, firmware_version) }, \
         { "firmware_git_hash", NULL, MAVLINK_TYPE_UINT32_T, 0, 12, offsetof(mavlink_kf_unit_status_t, firmware_git_hash) }, \
         { "dialect_hash", NULL, MAVLINK_TYPE_UINT32_T, 0, 16, offsetof(mavlink_kf_unit_status_t, dialect_hash) }, \
         { "samples", NULL, MAVLINK_TYPE_UINT32_T, 0, 20, offsetof(mavlink_kf_unit_status_t, samples) }, \
         { "samples_dropped", NULL, MAVLINK_TYPE_UINT32_T, 0, 24, offsetof(mavlink_kf_unit_status_t, samples_dropped) }, \
         { "frames_dropped", NULL, MAVLINK_TYPE_UINT32_T, 0, 28, offsetof(mavlink_kf_unit_status_t, frames_dropped) }, \
         { "rejected_samples", NULL, MAVLINK_TYPE_UINT32_T, 0, 32, offsetof(mavlink_kf_unit_status_t, rejected_samples) }, \
         { "crc_errors", NULL, MAVLINK_TYPE_UINT32_T, 0, 36, offsetof(mavlink_kf_unit_status_t, crc_errors) }, \
         { "unknown_messages", NULL, MAVLINK_TYPE_UINT32_T, 0, 40, offsetof(mavlink_kf_unit_status_t, unknown_messages) }, \
         { "param_rejects", NULL, MAVLINK_TYPE_UINT32_T, 0, 44, offsetof(mavlink_kf_unit_status_t, param_rejects) }, \
         { "sensor_rate_requested", NULL, MAVLINK_TYPE_FLOAT, 0, 48, offsetof(mavlink_kf_unit_status_t, sensor_rate_requested) }, \
         { "sensor_rate_achieved", NULL, MAVLINK_TYPE_FLOAT, 0, 52, offsetof(mavlink_kf_unit_status_t, sensor_rate_achieved) }, \
         { "raw_rate_requested", NULL, MAVLINK_TYPE_FLOAT, 0, 56, offsetof(mavlink_kf_unit_status_t, raw_rate_requested) }, \
         { "raw_rate_achieved", NULL, MAVLINK_TYPE_FLOAT, 0, 60, offsetof(mavlink_kf_unit_status_t, raw_rate_achieved) }, \
         { "orientation_rate_requested", NULL, MAVLINK_TYPE_FLOAT, 0, 64, offsetof(mavlink_kf_unit_status_t, orientation_rate_requested) }, \
         { "orientation_rate_achieved", NULL, MAVLINK_TYPE_FLOAT, 0, 68, offsetof(mavlink_kf_unit_status_t, orientation_rate_achieved) }, \
         { "battery_voltage", NULL, MAVLINK_TYPE_UINT16_T, 0, 72, offsetof(mavlink_kf_unit_status_t, battery_voltage) }, \
         { "cpu_load", NULL, MAVLINK_TYPE_UINT16_T, 0, 74, offsetof(mavlink_kf_unit_status_t, cpu_load) }, \
         { "status_flags", NULL, MAVLINK_TYPE_UINT16_T, 0, 76, offsetof(mavlink_kf_unit_status_t, status_flags) }, \
         { "battery_remaining", NULL, MAVLINK_TYPE_INT8_T, 0, 78, offsetof(mavlink_kf_unit_status_t, battery_remaining) }, \
         { "unit_id", NULL, MAVLINK_TYPE_UINT8_T, 0, 79, offsetof(mavlink_kf_unit_status_t, unit_id) }, \
         { "filter_id", NULL, MAVLINK_TYPE_UINT8_T, 0, 80, offsetof(mavlink_kf_unit_status_t, filter_id) }, \
         { "numeric_format", NULL, MAVLINK_TYPE_UINT8_T, 0, 81, offsetof(mavlink_kf_unit_status_t, numeric_format) }, \
         { "earth_frame", NULL, MAVLINK_TYPE_UINT8_T, 0, 82, offsetof(mavlink_kf_unit_status_t, earth_frame) }, \
         { "numeric_resets", NULL, MAVLINK_TYPE_UINT32_T, 0, 83, offsetof(mavlink_kf_unit_status_t, numeric_resets) }, \
         { "hil_invalid", NULL, MAVLINK_TYPE_UINT32_T, 0, 87, offsetof(mavlink_kf_unit_status_t, hil_invalid) }, \
         { "rejected_samples2", NULL, MAVLINK_TYPE_UINT32_T, 0, 91, offsetof(mavlink_kf_unit_status_t, rejected_samples2) }, \
         } \
}
#endif

/**
 * @brief Pack a kf_unit_status message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 *
 * @param time_boot_us [us] Unit clock, microseconds since boot.
 * @param firmware_version  Firmware version: major << 24 | minor << 16 | patch << 8 | FIRMWARE_VERSION_TYPE.
 * @param firmware_git_hash  First 32 bits of the firmware's git commit hash (0: unknown).
 * @param dialect_hash  KF_DIALECT_HASH of the MAVLink headers the firmware was built with (the host warns on mismatch).
 * @param samples  Sensor samples taken.
 * @param samples_dropped  Sensor samples lost on the unit (FIFO overrun, late read).
 * @param frames_dropped  Outgoing frames dropped because the transmit buffer was full.
 * @param rejected_samples  Samples rejected by the orientation filter.
 * @param crc_errors  Received frames with a bad CRC.
 * @param unknown_messages  Received frames with an unknown message id.
 * @param param_rejects  PARAM_SET requests rejected (unknown name, wrong type, out of range).
 * @param sensor_rate_requested [Hz] Requested sensor sample rate.
 * @param sensor_rate_achieved [Hz] Sensor sample rate achieved since the previous status, measured on the unit clock.
 * @param raw_rate_requested [Hz] Requested KF_RAW_SAMPLE stream rate (0: off).
 * @param raw_rate_achieved [Hz] KF_RAW_SAMPLE frames sent per second since the previous status.
 * @param orientation_rate_requested [Hz] Requested KF_ORIENTATION stream rate (0: off).
 * @param orientation_rate_achieved [Hz] KF_ORIENTATION frames sent per second since the previous status.
 * @param battery_voltage [mV] Battery voltage (UINT16_MAX: unknown).
 * @param cpu_load [d%] Processor load (0..1000).
 * @param status_flags  Status bits.
 * @param battery_remaining [%] Remaining battery charge (-1: unknown).
 * @param unit_id  Unit id.
 * @param filter_id  Orientation estimator running.
 * @param numeric_format  Arithmetic of the estimators.
 * @param earth_frame  Earth frame of KF_ORIENTATION.
 * @param numeric_resets  Orientation filter restarts after a non-finite state (either sensor's filter in two-sensor mode; each also sets NUMERIC_RESET in KF_ORIENTATION or KF_JOINT_ANGLE).
 * @param hil_invalid  HIL_SENSOR messages not processed: a NaN acc/gyro/mag value, or a sensor id the unit does not have (id 1 without two-sensor mode, id > 1).
 * @param rejected_samples2  Samples rejected by sensor 1's orientation filter (two-sensor mode, KF_JOINT_ID != 0; rejected_samples is sensor 0's).
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_kf_unit_status_pack(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg,
                               uint64_t time_boot_us, uint32_t firmware_version, uint32_t firmware_git_hash, uint32_t dialect_hash, uint32_t samples, uint32_t samples_dropped, uint32_t frames_dropped, uint32_t rejected_samples, uint32_t crc_errors, uint32_t unknown_messages, uint32_t param_rejects, float sensor_rate_requested, float sensor_rate_achieved, float raw_rate_requested, float raw_rate_achieved, float orientation_rate_requested, float orientation_rate_achieved, uint16_t battery_voltage, uint16_t cpu_load, uint16_t status_flags, int8_t battery_remaining, uint8_t unit_id, uint8_t filter_id, uint8_t numeric_format, uint8_t earth_frame, uint32_t numeric_resets, uint32_t hil_invalid, uint32_t rejected_samples2)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_KF_UNIT_STATUS_LEN];
    _mav_put_uint64_t(buf, 0, time_boot_us);
    _mav_put_uint32_t(buf, 8, firmware_version);
    _mav_put_uint32_t(buf, 12, firmware_git_hash);
    _mav_put_uint32_t(buf, 16, dialect_hash);
    _mav_put_uint32_t(buf, 20, samples);
    _mav_put_uint32_t(buf, 24, samples_dropped);
    _mav_put_uint32_t(buf, 28, frames_dropped);
    _mav_put_uint32_t(buf, 32, rejected_samples);
    _mav_put_uint32_t(buf, 36, crc_errors);
    _mav_put_uint32_t(buf, 40, unknown_messages);
    _mav_put_uint32_t(buf, 44, param_rejects);
    _mav_put_float(buf, 48, sensor_rate_requested);
    _mav_put_float(buf, 52, sensor_rate_achieved);
    _mav_put_float(buf, 56, raw_rate_requested);
    _mav_put_float(buf, 60, raw_rate_achieved);
    _mav_put_float(buf, 64, orientation_rate_requested);
    _mav_put_float(buf, 68, orientation_rate_achieved);
    _mav_put_uint16_t(buf, 72, battery_voltage);
    _mav_put_uint16_t(buf, 74, cpu_load);
    _mav_put_uint16_t(buf, 76, status_flags);
    _mav_put_int8_t(buf, 78, battery_remaining);
    _mav_put_uint8_t(buf, 79, unit_id);
    _mav_put_uint8_t(buf, 80, filter_id);
    _mav_put_uint8_t(buf, 81, numeric_format);
    _mav_put_uint8_t(buf, 82, earth_frame);
    _mav_put_uint32_t(buf, 83, numeric_resets);
    _mav_put_uint32_t(buf, 87, hil_invalid);
    _mav_put_uint32_t(buf, 91, rejected_samples2);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_KF_UNIT_STATUS_LEN);
#else
    mavlink_kf_unit_status_t packet;
    packet.time_boot_us = time_boot_us;
    packet.firmware_version = firmware_version;
    packet.firmware_git_hash = firmware_git_hash;
    packet.dialect_hash = dialect_hash;
    packet.samples = samples;
    packet.samples_dropped = samples_dropped;
    packet.frames_dropped = frames_dropped;
    packet.rejected_samples = rejected_samples;
    packet.crc_errors = crc_errors;
    packet.unknown_messages = unknown_messages;
    packet.param_rejects = param_rejects;
    packet.sensor_rate_requested = sensor_rate_requested;
    packet.sensor_rate_achieved = sensor_rate_achieved;
    packet.raw_rate_requested = raw_rate_requested;
    packet.raw_rate_achieved = raw_rate_achieved;
    packet.orientation_rate_requested = orientation_rate_requested;
    packet.orientation_rate_achieved = orientation_rate_achieved;
    packet.battery_voltage = battery_voltage;
    packet.cpu_load = cpu_load;
    packet.status_flags = status_flags;
    packet.battery_remaining = battery_remaining;
    packet.unit_id = unit_id;
    packet.filter_id = filter_id;
    packet.numeric_format = numeric_format;
    packet.earth_frame = earth_frame;
    packet.numeric_resets = numeric_resets;
    packet.hil_invalid = hil_invalid;
    packet.rejected_samples2 = rejected_samples2;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_KF_UNIT_STATUS_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_KF_UNIT_STATUS;
    return mavlink_finalize_message(msg, system_id, component_id, MAVLINK_MSG_ID_KF_UNIT_STATUS_MIN_LEN, MAVLINK_MSG_ID_KF_UNIT_STATUS_LEN, MAVLINK_MSG_ID_KF_UNIT_STATUS_CRC);
}

/**
 * @brief Pack a kf_unit_status message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 *
 * @param time_boot_us [us] Unit clock, microseconds since boot.
 * @param firmware_version  Firmware version: major << 24 | minor << 16 | patch << 8 | FIRMWARE_VERSION_TYPE.
 * @param firmware_git_hash  First 32 bits of the firmware's git commit hash (0: unknown).
 * @param dialect_hash  KF_DIALECT_HASH of the MAVLink headers the firmware was built with (the host warns on mismatch).
 * @param samples  Sensor samples taken.
 * @param samples_dropped  Sensor samples lost on the unit (FIFO overrun, late read).
 * @param frames_dropped  Outgoing frames dropped because the transmit buffer was full.
 * @param rejected_samples  Samples rejected by the orientation filter.
 * @param crc_errors  Received frames with a bad CRC.
 * @param unknown_messages  Received frames with an unknown message id.
 * @param param_rejects  PARAM_SET requests rejected (unknown name, wrong type, out of range).
 * @param sensor_rate_requested [Hz] Requested sensor sample rate.
 * @param sensor_rate_achieved [Hz] Sensor sample rate achieved since the previous status, measured on the unit clock.
 * @param raw_rate_requested [Hz] Requested KF_RAW_SAMPLE stream rate (0: off).
 * @param raw_rate_achieved [Hz] KF_RAW_SAMPLE frames sent per second since the previous status.
 * @param orientation_rate_requested [Hz] Requested KF_ORIENTATION stream rate (0: off).
 * @param orientation_rate_achieved [Hz] KF_ORIENTATION frames sent per second since the previous status.
 * @param battery_voltage [mV] Battery voltage (UINT16_MAX: unknown).
 * @param cpu_load [d%] Processor load (0..1000).
 * @param status_flags  Status bits.
 * @param battery_remaining [%] Remaining battery charge (-1: unknown).
 * @param unit_id  Unit id.
 * @param filter_id  Orientation estimator running.
 * @param numeric_format  Arithmetic of the estimators.
 * @param earth_frame  Earth frame of KF_ORIENTATION.
 * @param numeric_resets  Orientation filter restarts after a non-finite state (either sensor's filter in two-sensor mode; each also sets NUMERIC_RESET in KF_ORIENTATION or KF_JOINT_ANGLE).
 * @param hil_invalid  HIL_SENSOR messages not processed: a NaN acc/gyro/mag value, or a sensor id the unit does not have (id 1 without two-sensor mode, id > 1).
 * @param rejected_samples2  Samples rejected by sensor 1's orientation filter (two-sensor mode, KF_JOINT_ID != 0; rejected_samples is sensor 0's).
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_kf_unit_status_pack_status(uint8_t system_id, uint8_t component_id, mavlink_status_t *_status, mavlink_message_t* msg,
                               uint64_t time_boot_us, uint32_t firmware_version, uint32_t firmware_git_hash, uint32_t dialect_hash, uint32_t samples, uint32_t samples_dropped, uint32_t frames_dropped, uint32_t rejected_samples, uint32_t crc_errors, uint32_t unknown_messages, uint32_t param_rejects, float sensor_rate_requested, float sensor_rate_achieved, float raw_rate_requested, float raw_rate_achieved, float orientation_rate_requested, float orientation_rate_achieved, uint16_t battery_voltage, uint16_t cpu_load, uint16_t status_flags, int8_t battery_remaining, uint8_t unit_id, uint8_t filter_id, uint8_t numeric_format, uint8_t earth_frame, uint32_t numeric_resets, uint32_t hil_invalid, uint32_t rejected_samples2)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_KF_UNIT_STATUS_LEN];
    _mav_put_uint64_t(buf, 0, time_boot_us);
    _mav_put_uint32_t(buf, 8, firmware_version);
    _mav_put_uint32_t(buf, 12, firmware_git_hash);
    _mav_put_uint32_t(buf, 16, dialect_hash);
    _mav_put_uint32_t(buf, 20, samples);
    _mav_put_uint32_t(buf, 24, samples_dropped);
    _mav_put_uint32_t(buf, 28, frames_dropped);
    _mav_put_uint32_t(buf, 32, rejected_samples);
    _mav_put_uint32_t(buf, 36, crc_errors);
    _mav_put_uint32_t(buf, 40, unknown_messages);
    _mav_put_uint32_t(buf, 44, param_rejects);
    _mav_put_float(buf, 48, sensor_rate_requested);
    _mav_put_float(buf, 52, sensor_rate_achieved);
    _mav_put_float(buf, 56, raw_rate_requested);
    _mav_put_float(buf, 60, raw_rate_achieved);
    _mav_put_float(buf, 64, orientation_rate_requested);
    _mav_put_float(buf, 68, orientation_rate_achieved);
    _mav_put_uint16_t(buf, 72, battery_voltage);
    _mav_put_uint16_t(buf, 74, cpu_load);
    _mav_put_uint16_t(buf, 76, status_flags);
    _mav_put_int8_t(buf, 78, battery_remaining);
    _mav_put_uint8_t(buf, 79, unit_id);
    _mav_put_uint8_t(buf, 80, filter_id);
    _mav_put_uint8_t(buf, 81, numeric_format);
    _mav_put_uint8_t(buf, 82, earth_frame);
    _mav_put_uint32_t(buf, 83, numeric_resets);
    _mav_put_uint32_t(buf, 87, hil_invalid);
    _mav_put_uint32_t(buf, 91, rejected_samples2);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_KF_UNIT_STATUS_LEN);
#else
    mavlink_kf_unit_status_t packet;
    packet.time_boot_us = time_boot_us;
    packet.firmware_version = firmware_version;
    packet.firmware_git_hash = firmware_git_hash;
    packet.dialect_hash = dialect_hash;
    packet.samples = samples;
    packet.samples_dropped = samples_dropped;
    packet.frames_dropped = frames_dropped;
    packet.rejected_samples = rejected_samples;
    packet.crc_errors = crc_errors;
    packet.unknown_messages = unknown_messages;
    packet.param_rejects = param_rejects;
    packet.sensor_rate_requested = sensor_rate_requested;
    packet.sensor_rate_achieved = sensor_rate_achieved;
    packet.raw_rate_requested = raw_rate_requested;
    packet.raw_rate_achieved = raw_rate_achieved;
    packet.orientation_rate_requested = orientation_rate_requested;
    packet.orientation_rate_achieved = orientation_rate_achieved;
    packet.battery_voltage = battery_voltage;
    packet.cpu_load = cpu_load;
    packet.status_flags = status_flags;
    packet.battery_remaining = battery_remaining;
    packet.unit_id = unit_id;
    packet.filter_id = filter_id;
    packet.numeric_format = numeric_format;
    packet.earth_frame = earth_frame;
    packet.numeric_resets = numeric_resets;
    packet.hil_invalid = hil_invalid;
    packet.rejected_samples2 = rejected_samples2;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_KF_UNIT_STATUS_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_KF_UNIT_STATUS;
#if MAVLINK_CRC_EXTRA
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_KF_UNIT_STATUS_MIN_LEN, MAVLINK_MSG_ID_KF_UNIT_STATUS_LEN, MAVLINK_MSG_ID_KF_UNIT_STATUS_CRC);
#else
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_KF_UNIT_STATUS_MIN_LEN, MAVLINK_MSG_ID_KF_UNIT_STATUS_LEN);
#endif
}

/**
 * @brief Pack a kf_unit_status message on a channel
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param time_boot_us [us] Unit clock, microseconds since boot.
 * @param firmware_version  Firmware version: major << 24 | minor << 16 | patch << 8 | FIRMWARE_VERSION_TYPE.
 * @param firmware_git_hash  First 32 bits of the firmware's git commit hash (0: unknown).
 * @param dialect_hash  KF_DIALECT_HASH of the MAVLink headers the firmware was built with (the host warns on mismatch).
 * @param samples  Sensor samples taken.
 * @param samples_dropped  Sensor samples lost on the unit (FIFO overrun, late read).
 * @param frames_dropped  Outgoing frames dropped because the transmit buffer was full.
 * @param rejected_samples  Samples rejected by the orientation filter.
 * @param crc_errors  Received frames with a bad CRC.
 * @param unknown_messages  Received frames with an unknown message id.
 * @param param_rejects  PARAM_SET requests rejected (unknown name, wrong type, out of range).
 * @param sensor_rate_requested [Hz] Requested sensor sample rate.
 * @param sensor_rate_achieved [Hz] Sensor sample rate achieved since the previous status, measured on the unit clock.
 * @param raw_rate_requested [Hz] Requested KF_RAW_SAMPLE stream rate (0: off).
 * @param raw_rate_achieved [Hz] KF_RAW_SAMPLE frames sent per second since the previous status.
 * @param orientation_rate_requested [Hz] Requested KF_ORIENTATION stream rate (0: off).
 * @param orientation_rate_achieved [Hz] KF_ORIENTATION frames sent per second since the previous status.
 * @param battery_voltage [mV] Battery voltage (UINT16_MAX: unknown).
 * @param cpu_load [d%] Processor load (0..1000).
 * @param status_flags  Status bits.
 * @param battery_remaining [%] Remaining battery charge (-1: unknown).
 * @param unit_id  Unit id.
 * @param filter_id  Orientation estimator running.
 * @param numeric_format  Arithmetic of the estimators.
 * @param earth_frame  Earth frame of KF_ORIENTATION.
 * @param numeric_resets  Orientation filter restarts after a non-finite state (either sensor's filter in two-sensor mode; each also sets NUMERIC_RESET in KF_ORIENTATION or KF_JOINT_ANGLE).
 * @param hil_invalid  HIL_SENSOR messages not processed: a NaN acc/gyro/mag value, or a sensor id the unit does not have (id 1 without two-sensor mode, id > 1).
 * @param rejected_samples2  Samples rejected by sensor 1's orientation filter (two-sensor mode, KF_JOINT_ID != 0; rejected_samples is sensor 0's).
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_kf_unit_status_pack_chan(uint8_t system_id, uint8_t component_id, uint8_t chan,
                               mavlink_message_t* msg,
                                   uint64_t time_boot_us,uint32_t firmware_version,uint32_t firmware_git_hash,uint32_t dialect_hash,uint32_t samples,uint32_t samples_dropped,uint32_t frames_dropped,uint32_t rejected_samples,uint32_t crc_errors,uint32_t unknown_messages,uint32_t param_rejects,float sensor_rate_requested,float sensor_rate_achieved,float raw_rate_requested,float raw_rate_achieved,float orientation_rate_requested,float orientation_rate_achieved,uint16_t battery_voltage,uint16_t cpu_load,uint16_t status_flags,int8_t battery_remaining,uint8_t unit_id,uint8_t filter_id,uint8_t numeric_format,uint8_t earth_frame,uint32_t numeric_resets,uint32_t hil_invalid,uint32_t rejected_samples2)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_KF_UNIT_STATUS_LEN];
    _mav_put_uint64_t(buf, 0, time_boot_us);
    _mav_put_uint32_t(buf, 8, firmware_version);
    _mav_put_uint32_t(buf, 12, firmware_git_hash);
    _mav_put_uint32_t(buf, 16, dialect_hash);
    _mav_put_uint32_t(buf, 20, samples);
    _mav_put_uint32_t(buf, 24, samples_dropped);
    _mav_put_uint32_t(buf, 28, frames_dropped);
    _mav_put_uint32_t(buf, 32, rejected_samples);
    _mav_put_uint32_t(buf, 36, crc_errors);
    _mav_put_uint32_t(buf, 40, unknown_messages);
    _mav_put_uint32_t(buf, 44, param_rejects);
    _mav_put_float(buf, 48, sensor_rate_requested);
    _mav_put_float(buf, 52, sensor_rate_achieved);
    _mav_put_float(buf, 56, raw_rate_requested);
    _mav_put_float(buf, 60, raw_rate_achieved);
    _mav_put_float(buf, 64, orientation_rate_requested);
    _mav_put_float(buf, 68, orientation_rate_achieved);
    _mav_put_uint16_t(buf, 72, battery_voltage);
    _mav_put_uint16_t(buf, 74, cpu_load);
    _mav_put_uint16_t(buf, 76, status_flags);
    _mav_put_int8_t(buf, 78, battery_remaining);
    _mav_put_uint8_t(buf, 79, unit_id);
    _mav_put_uint8_t(buf, 80, filter_id);
    _mav_put_uint8_t(buf, 81, numeric_format);
    _mav_put_uint8_t(buf, 82, earth_frame);
    _mav_put_uint32_t(buf, 83, numeric_resets);
    _mav_put_uint32_t(buf, 87, hil_invalid);
    _mav_put_uint32_t(buf, 91, rejected_samples2);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_KF_UNIT_STATUS_LEN);
#else
    mavlink_kf_unit_status_t packet;
    packet.time_boot_us = time_boot_us;
    packet.firmware_version = firmware_version;
    packet.firmware_git_hash = firmware_git_hash;
    packet.dialect_hash = dialect_hash;
    packet.samples = samples;
    packet.samples_dropped = samples_dropped;
    packet.frames_dropped = frames_dropped;
    packet.rejected_samples = rejected_samples;
    packet.crc_errors = crc_errors;
    packet.unknown_messages = unknown_messages;
    packet.param_rejects = param_rejects;
    packet.sensor_rate_requested = sensor_rate_requested;
    packet.sensor_rate_achieved = sensor_rate_achieved;
    packet.raw_rate_requested = raw_rate_requested;
    packet.raw_rate_achieved = raw_rate_achieved;
    packet.orientation_rate_requested = orientation_rate_requested;
    packet.orientation_rate_achieved = orientation_rate_achieved;
    packet.battery_voltage = battery_voltage;
    packet.cpu_load = cpu_load;
    packet.status_flags = status_flags;
    packet.battery_remaining = battery_remaining;
    packet.unit_id = unit_id;
    packet.filter_id = filter_id;
    packet.numeric_format = numeric_format;
    packet.earth_frame = earth_frame;
    packet.numeric_resets = numeric_resets;
    packet.hil_invalid = hil_invalid;
    packet.rejected_samples2 = rejected_samples2;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_KF_UNIT_STATUS_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_KF_UNIT_STATUS;
    return mavlink_finalize_message_chan(msg, system_id, component_id, chan, MAVLINK_MSG_ID_KF_UNIT_STATUS_MIN_LEN, MAVLINK_MSG_ID_KF_UNIT_STATUS_LEN, MAVLINK_MSG_ID_KF_UNIT_STATUS_CRC);
}

/**
 * @brief Encode a kf_unit_status struct
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 * @param kf_unit_status C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_kf_unit_status_encode(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg, const mavlink_kf_unit_status_t* kf_unit_status)
{
    return mavlink_msg_kf_unit_status_pack(system_id, component_id, msg, kf_unit_status->time_boot_us, kf_unit_status->firmware_version, kf_unit_status->firmware_git_hash, kf_unit_status->dialect_hash, kf_unit_status->samples, kf_unit_status->samples_dropped, kf_unit_status->frames_dropped, kf_unit_status->rejected_samples, kf_unit_status->crc_errors, kf_unit_status->unknown_messages, kf_unit_status->param_rejects, kf_unit_status->sensor_rate_requested, kf_unit_status->sensor_rate_achieved, kf_unit_status->raw_rate_requested, kf_unit_status->raw_rate_achieved, kf_unit_status->orientation_rate_requested, kf_unit_status->orientation_rate_achieved, kf_unit_status->battery_voltage, kf_unit_status->cpu_load, kf_unit_status->status_flags, kf_unit_status->battery_remaining, kf_unit_status->unit_id, kf_unit_status->filter_id, kf_unit_status->numeric_format, kf_unit_status->earth_frame, kf_unit_status->numeric_resets, kf_unit_status->hil_invalid, kf_unit_status->rejected_samples2);
}

/**
 * @brief Encode a kf_unit_status struct on a channel
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param kf_unit_status C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_kf_unit_status_encode_chan(uint8_t system_id, uint8_t component_id, uint8_t chan, mavlink_message_t* msg, const mavlink_kf_unit_status_t* kf_unit_status)
{
    return mavlink_msg_kf_unit_status_pack_chan(system_id, component_id, chan, msg, kf_unit_status->time_boot_us, kf_unit_status->firmware_version, kf_unit_status->firmware_git_hash, kf_unit_status->dialect_hash, kf_unit_status->samples, kf_unit_status->samples_dropped, kf_unit_status->frames_dropped, kf_unit_status->rejected_samples, kf_unit_status->crc_errors, kf_unit_status->unknown_messages, kf_unit_status->param_rejects, kf_unit_status->sensor_rate_requested, kf_unit_status->sensor_rate_achieved, kf_unit_status->raw_rate_requested, kf_unit_status->raw_rate_achieved, kf_unit_status->orientation_rate_requested, kf_unit_status->orientation_rate_achieved, kf_unit_status->battery_voltage, kf_unit_status->cpu_load, kf_unit_status->status_flags, kf_unit_status->battery_remaining, kf_unit_status->unit_id, kf_unit_status->filter_id, kf_unit_status->numeric_format, kf_unit_status->earth_frame, kf_unit_status->numeric_resets, kf_unit_status->hil_invalid, kf_unit_status->rejected_samples2);
}

/**
 * @brief Encode a kf_unit_status struct with provided status structure
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 * @param kf_unit_status C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_kf_unit_status_encode_status(uint8_t system_id, uint8_t component_id, mavlink_status_t* _status, mavlink_message_t* msg, const mavlink_kf_unit_status_t* kf_unit_status)
{
    return mavlink_msg_kf_unit_status_pack_status(system_id, component_id, _status, msg,  kf_unit_status->time_boot_us, kf_unit_status->firmware_version, kf_unit_status->firmware_git_hash, kf_unit_status->dialect_hash, kf_unit_status->samples, kf_unit_status->samples_dropped, kf_unit_status->frames_dropped, kf_unit_status->rejected_samples, kf_unit_status->crc_errors, kf_unit_status->unknown_messages, kf_unit_status->param_rejects, kf_unit_status->sensor_rate_requested, kf_unit_status->sensor_rate_achieved, kf_unit_status->raw_rate_requested, kf_unit_status->raw_rate_achieved, kf_unit_status->orientation_rate_requested, kf_unit_status->orientation_rate_achieved, kf_unit_status->battery_voltage, kf_unit_status->cpu_load, kf_unit_status->status_flags, kf_unit_status->battery_remaining, kf_unit_status->unit_id, kf_unit_status->filter_id, kf_unit_status->numeric_format, kf_unit_status->earth_frame, kf_unit_status->numeric_resets, kf_unit_status->hil_invalid, kf_unit_status->rejected_samples2);
}

/**
 * @brief Send a kf_unit_status message
 * @param chan MAVLink channel to send the message
 *
 * @param time_boot_us [us] Unit clock, microseconds since boot.
 * @param firmware_version  Firmware version: major << 24 | minor << 16 | patch << 8 | FIRMWARE_VERSION_TYPE.
 * @param firmware_git_hash  First 32 bits of the firmware's git commit hash (0: unknown).
 * @param dialect_hash  KF_DIALECT_HASH of the MAVLink headers the firmware was built with (the host warns on mismatch).
 * @param samples  Sensor samples taken.
 * @param samples_dropped  Sensor samples lost on the unit (FIFO overrun, late read).
 * @param frames_dropped  Outgoing frames dropped because the transmit buffer was full.
 * @param rejected_samples  Samples rejected by the orientation filter.
 * @param crc_errors  Received frames with a bad CRC.
 * @param unknown_messages  Received frames with an unknown message id.
 * @param param_rejects  PARAM_SET requests rejected (unknown name, wrong type, out of range).
 * @param sensor_rate_requested [Hz] Requested sensor sample rate.
 * @param sensor_rate_achieved [Hz] Sensor sample rate achieved since the previous status, measured on the unit clock.
 * @param raw_rate_requested [Hz] Requested KF_RAW_SAMPLE stream rate (0: off).
 * @param raw_rate_achieved [Hz] KF_RAW_SAMPLE frames sent per second since the previous status.
 * @param orientation_rate_requested [Hz] Requested KF_ORIENTATION stream rate (0: off).
 * @param orientation_rate_achieved [Hz] KF_ORIENTATION frames sent per second since the previous status.
 * @param battery_voltage [mV] Battery voltage (UINT16_MAX: unknown).
 * @param cpu_load [d%] Processor load (0..1000).
 * @param status_flags  Status bits.
 * @param battery_remaining [%] Remaining battery charge (-1: unknown).
 * @param unit_id  Unit id.
 * @param filter_id  Orientation estimator running.
 * @param numeric_format  Arithmetic of the estimators.
 * @param earth_frame  Earth frame of KF_ORIENTATION.
 * @param numeric_resets  Orientation filter restarts after a non-finite state (either sensor's filter in two-sensor mode; each also sets NUMERIC_RESET in KF_ORIENTATION or KF_JOINT_ANGLE).
 * @param hil_invalid  HIL_SENSOR messages not processed: a NaN acc/gyro/mag value, or a sensor id the unit does not have (id 1 without two-sensor mode, id > 1).
 * @param rejected_samples2  Samples rejected by sensor 1's orientation filter (two-sensor mode, KF_JOINT_ID != 0; rejected_samples is sensor 0's).
 */
#ifdef MAVLINK_USE_CONVENIENCE_FUNCTIONS

static inline void mavlink_msg_kf_unit_status_send(mavlink_channel_t chan, uint64_t time_boot_us, uint32_t firmware_version, uint32_t firmware_git_hash, uint32_t dialect_hash, uint32_t samples, uint32_t samples_dropped, uint32_t frames_dropped, uint32_t rejected_samples, uint32_t crc_errors, uint32_t unknown_messages, uint32_t param_rejects, float sensor_rate_requested, float sensor_rate_achieved, float raw_rate_requested, float raw_rate_achieved, float orientation_rate_requested, float orientation_rate_achieved, uint16_t battery_voltage, uint16_t cpu_load, uint16_t status_flags, int8_t battery_remaining, uint8_t unit_id, uint8_t filter_id, uint8_t numeric_format, uint8_t earth_frame, uint32_t numeric_resets, uint32_t hil_invalid, uint32_t rejected_samples2)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_KF_UNIT_STATUS_LEN];
    _mav_put_uint64_t(buf, 0, time_boot_us);
    _mav_put_uint32_t(buf, 8, firmware_version);
    _mav_put_uint32_t(buf, 12, firmware_git_hash);
    _mav_put_uint32_t(buf, 16, dialect_hash);
    _mav_put_uint32_t(buf, 20, samples);
    _mav_put_uint32_t(buf, 24, samples_dropped);
    _mav_put_uint32_t(buf, 28, frames_dropped);
    _mav_put_uint32_t(buf, 32, rejected_samples);
    _mav_put_uint32_t(buf, 36, crc_errors);
    _mav_put_uint32_t(buf, 40, unknown_messages);
    _mav_put_uint32_t(buf, 44, param_rejects);
    _mav_put_float(buf, 48, sensor_rate_requested);
    _mav_put_float(buf, 52, sensor_rate_achieved);
    _mav_put_float(buf, 56, raw_rate_requested);
    _mav_put_float(buf, 60, raw_rate_achieved);
    _mav_put_float(buf, 64, orientation_rate_requested);
    _mav_put_float(buf, 68, orientation_rate_achieved);
    _mav_put_uint16_t(buf, 72, battery_voltage);
    _mav_put_uint16_t(buf, 74, cpu_load);
    _mav_put_uint16_t(buf, 76, status_flags);
    _mav_put_int8_t(buf, 78, battery_remaining);
    _mav_put_uint8_t(buf, 79, unit_id);
    _mav_put_uint8_t(buf, 80, filter_id);
    _mav_put_uint8_t(buf, 81, numeric_format);
    _mav_put_uint8_t(buf, 82, earth_frame);
    _mav_put_uint32_t(buf, 83, numeric_resets);
    _mav_put_uint32_t(buf, 87, hil_invalid);
    _mav_put_uint32_t(buf, 91, rejected_samples2);

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_KF_UNIT_STATUS, buf, MAVLINK_MSG_ID_KF_UNIT_STATUS_MIN_LEN, MAVLINK_MSG_ID_KF_UNIT_STATUS_LEN, MAVLINK_MSG_ID_KF_UNIT_STATUS_CRC);
#else
    mavlink_kf_unit_status_t packet;
    packet.time_boot_us = time_boot_us;
    packet.firmware_version = firmware_version;
    packet.firmware_git_hash = firmware_git_hash;
    packet.dialect_hash = dialect_hash;
    packet.samples = samples;
    packet.samples_dropped = samples_dropped;
    packet.frames_dropped = frames_dropped;
    packet.rejected_samples = rejected_samples;
    packet.crc_errors = crc_errors;
    packet.unknown_messages = unknown_messages;
    packet.param_rejects = param_rejects;
    packet.sensor_rate_requested = sensor_rate_requested;
    packet.sensor_rate_achieved = sensor_rate_achieved;
    packet.raw_rate_requested = raw_rate_requested;
    packet.raw_rate_achieved = raw_rate_achieved;
    packet.orientation_rate_requested = orientation_rate_requested;
    packet.orientation_rate_achieved = orientation_rate_achieved;
    packet.battery_voltage = battery_voltage;
    packet.cpu_load = cpu_load;
    packet.status_flags = status_flags;
    packet.battery_remaining = battery_remaining;
    packet.unit_id = unit_id;
    packet.filter_id = filter_id;
    packet.numeric_format = numeric_format;
    packet.earth_frame = earth_frame;
    packet.numeric_resets = numeric_resets;
    packet.hil_invalid = hil_invalid;
    packet.rejected_samples2 = rejected_samples2;

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_KF_UNIT_STATUS, (const char *)&packet, MAVLINK_MSG_ID_KF_UNIT_STATUS_MIN_LEN, MAVLINK_MSG_ID_KF_UNIT_STATUS_LEN, MAVLINK_MSG_ID_KF_UNIT_STATUS_CRC);
#endif
}

/**
 * @brief Send a kf_unit_status message
 * @param chan MAVLink channel to send the message
 * @param struct The MAVLink struct to serialize
 */
static inline void mavlink_msg_kf_unit_status_send_struct(mavlink_channel_t chan, const mavlink_kf_unit_status_t* kf_unit_status)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    mavlink_msg_kf_unit_status_send(chan, kf_unit_status->time_boot_us, kf_unit_status->firmware_version, kf_unit_status->firmware_git_hash, kf_unit_status->dialect_hash, kf_unit_status->samples, kf_unit_status->samples_dropped, kf_unit_status->frames_dropped, kf_unit_status->rejected_samples, kf_unit_status->crc_errors, kf_unit_status->unknown_messages, kf_unit_status->param_rejects, kf_unit_status->sensor_rate_requested, kf_unit_status->sensor_rate_achieved, kf_unit_status->raw_rate_requested, kf_unit_status->raw_rate_achieved, kf_unit_status->orientation_rate_requested, kf_unit_status->orientation_rate_achieved, kf_unit_status->battery_voltage, kf_unit_status->cpu_load, kf_unit_status->status_flags, kf_unit_status->battery_remaining, kf_unit_status->unit_id, kf_unit_status->filter_id, kf_unit_status->numeric_format, kf_unit_status->earth_frame, kf_unit_status->numeric_resets, kf_unit_status->hil_invalid, kf_unit_status->rejected_samples2);
#else
    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_KF_UNIT_STATUS, (const char *)kf_unit_status, MAVLINK_MSG_ID_KF_UNIT_STATUS_MIN_LEN, MAVLINK_MSG_ID_KF_UNIT_STATUS_LEN, MAVLINK_MSG_ID_KF_UNIT_STATUS_CRC);
#endif
}

#if MAVLINK_MSG_ID_KF_UNIT_STATUS_LEN <= MAVLINK_MAX_PAYLOAD_LEN
/*
  This variant of _send() can be used to save stack space by reusing
  memory from the receive buffer.  The caller provides a
  mavlink_message_t which is the size of a full mavlink message. This
  is usually the receive buffer for the channel, and allows a reply to an
  incoming message with minimum stack space usage.
 */
static inline void mavlink_msg_kf_unit_status_send_buf(mavlink_message_t *msgbuf, mavlink_channel_t chan,  uint64_t time_boot_us, uint32_t firmware_version, uint32_t firmware_git_hash, uint32_t dialect_hash, uint32_t samples, uint32_t samples_dropped, uint32_t frames_dropped, uint32_t rejected_samples, uint32_t crc_errors, uint32_t unknown_messages, uint32_t param_rejects, float sensor_rate_requested, float sensor_rate_achieved, float raw_rate_requested, float raw_rate_achieved, float orientation_rate_requested, float orientation_rate_achieved, uint16_t battery_voltage, uint16_t cpu_load, uint16_t status_flags, int8_t battery_remaining, uint8_t unit_id, uint8_t filter_id, uint8_t numeric_format, uint8_t earth_frame, uint32_t numeric_resets, uint32_t hil_invalid, uint32_t rejected_samples2)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char *buf = (char *)msgbuf;
    _mav_put_uint64_t(buf, 0, time_boot_us);
    _mav_put_uint32_t(buf, 8, firmware_version);
    _mav_put_uint32_t(buf, 12, firmware_git_hash);
    _mav_put_uint32_t(buf, 16, dialect_hash);
    _mav_put_uint32_t(buf, 20, samples);
    _mav_put_uint32_t(buf, 24, samples_dropped);
    _mav_put_uint32_t(buf, 28, frames_dropped);
    _mav_put_uint32_t(buf, 32, rejected_samples);
    _mav_put_uint32_t(buf, 36, crc_errors);
    _mav_put_uint32_t(buf, 40, unknown_messages);
    _mav_put_uint32_t(buf, 44, param_rejects);
    _mav_put_float(buf, 48, sensor_rate_requested);
    _mav_put_float(buf, 52, sensor_rate_achieved);
    _mav_put_float(buf, 56, raw_rate_requested);
    _mav_put_float(buf, 60, raw_rate_achieved);
    _mav_put_float(buf, 64, orientation_rate_requested);
    _mav_put_float(buf, 68, orientation_rate_achieved);
    _mav_put_uint16_t(buf, 72, battery_voltage);
    _mav_put_uint16_t(buf, 74, cpu_load);
    _mav_put_uint16_t(buf, 76, status_flags);
    _mav_put_int8_t(buf, 78, battery_remaining);
    _mav_put_uint8_t(buf, 79, unit_id);
    _mav_put_uint8_t(buf, 80, filter_id);
    _mav_put_uint8_t(buf, 81, numeric_format);
    _mav_put_uint8_t(buf, 82, earth_frame);
    _mav_put_uint32_t(buf, 83, numeric_resets);
    _mav_put_uint32_t(buf, 87, hil_invalid);
    _mav_put_uint32_t(buf, 91, rejected_samples2);

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_KF_UNIT_STATUS, buf, MAVLINK_MSG_ID_KF_UNIT_STATUS_MIN_LEN, MAVLINK_MSG_ID_KF_UNIT_STATUS_LEN, MAVLINK_MSG_ID_KF_UNIT_STATUS_CRC);
#else
    mavlink_kf_unit_status_t *packet = (mavlink_kf_unit_status_t *)msgbuf;
    packet->time_boot_us = time_boot_us;
    packet->firmware_version = firmware_version;
    packet->firmware_git_hash = firmware_git_hash;
    packet->dialect_hash = dialect_hash;
    packet->samples = samples;
    packet->samples_dropped = samples_dropped;
    packet->frames_dropped = frames_dropped;
    packet->rejected_samples = rejected_samples;
    packet->crc_errors = crc_errors;
    packet->unknown_messages = unknown_messages;
    packet->param_rejects = param_rejects;
    packet->sensor_rate_requested = sensor_rate_requested;
    packet->sensor_rate_achieved = sensor_rate_achieved;
    packet->raw_rate_requested = raw_rate_requested;
    packet->raw_rate_achieved = raw_rate_achieved;
    packet->orientation_rate_requested = orientation_rate_requested;
    packet->orientation_rate_achieved = orientation_rate_achieved;
    packet->battery_voltage = battery_voltage;
    packet->cpu_load = cpu_load;
    packet->status_flags = status_flags;
    packet->battery_remaining = battery_remaining;
    packet->unit_id = unit_id;
    packet->filter_id = filter_id;
    packet->numeric_format = numeric_format;
    packet->earth_frame = earth_frame;
    packet->numeric_resets = numeric_resets;
    packet->hil_invalid = hil_invalid;
    packet->rejected_samples2 = rejected_samples2;

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_KF_UNIT_STATUS, (const char *)packet, MAVLINK_MSG_ID_KF_UNIT_STATUS_MIN_LEN, MAVLINK_MSG_ID_KF_UNIT_STATUS_LEN, MAVLINK_MSG_ID_KF_UNIT_STATUS_CRC);
#endif
}
#endif

#endif

// MESSAGE KF_UNIT_STATUS UNPACKING


/**
 * @brief Get field time_boot_us from kf_unit_status message
 *
 * @return [us] Unit clock, microseconds since boot.
 */
static inline uint64_t mavlink_msg_kf_unit_status_get_time_boot_us(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint64_t(msg,  0);
}

/**
 * @brief Get field firmware_version from kf_unit_status message
 *
 * @return  Firmware version: major << 24 | minor << 16 | patch << 8 | FIRMWARE_VERSION_TYPE.
 */
static inline uint32_t mavlink_msg_kf_unit_status_get_firmware_version(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  8);
}

/**
 * @brief Get field firmware_git_hash from kf_unit_status message
 *
 * @return  First 32 bits of the firmware's git commit hash (0: unknown).
 */
static inline uint32_t mavlink_msg_kf_unit_status_get_firmware_git_hash(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  12);
}

/**
 * @brief Get field dialect_hash from kf_unit_status message
 *
 * @return  KF_DIALECT_HASH of the MAVLink headers the firmware was built with (the host warns on mismatch).
 */
static inline uint32_t mavlink_msg_kf_unit_status_get_dialect_hash(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  16);
}

/**
 * @brief Get field samples from kf_unit_status message
 *
 * @return  Sensor samples taken.
 */
static inline uint32_t mavlink_msg_kf_unit_status_get_samples(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  20);
}

/**
 * @brief Get field samples_dropped from kf_unit_status message
 *
 * @return  Sensor samples lost on the unit (FIFO overrun, late read).
 */
static inline uint32_t mavlink_msg_kf_unit_status_get_samples_dropped(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  24);
}

/**
 * @brief Get field frames_dropped from kf_unit_status message
 *
 * @return  Outgoing frames dropped because the transmit buffer was full.
 */
static inline uint32_t mavlink_msg_kf_unit_status_get_frames_dropped(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  28);
}

/**
 * @brief Get field rejected_samples from kf_unit_status message
 *
 * @return  Samples rejected by the orientation filter.
 */
static inline uint32_t mavlink_msg_kf_unit_status_get_rejected_samples(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  32);
}

/**
 * @brief Get field crc_errors from kf_unit_status message
 *
 * @return  Received frames with a bad CRC.
 */
static inline uint32_t mavlink_msg_kf_unit_status_get_crc_errors(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  36);
}

/**
 * @brief Get field unknown_messages from kf_unit_status message
 *
 * @return  Received frames with an unknown message id.
 */
static inline uint32_t mavlink_msg_kf_unit_status_get_unknown_messages(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  40);
}

/**
 * @brief Get field param_rejects from kf_unit_status message
 *
 * @return  PARAM_SET requests rejected (unknown name, wrong type, out of range).
 */
static inline uint32_t mavlink_msg_kf_unit_status_get_param_rejects(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  44);
}

/**
 * @brief Get field sensor_rate_requested from kf_unit_status message
 *
 * @return [Hz] Requested sensor sample rate.
 */
static inline float mavlink_msg_kf_unit_status_get_sensor_rate_requested(const mavlink_message_t* msg)
{
    return _MAV_RETURN_float(msg,  48);
}

/**
 * @brief Get field sensor_rate_achieved from kf_unit_status message
 *
 * @return [Hz] Sensor sample rate achieved since the previous status, measured on the unit clock.
 */
static inline float mavlink_msg_kf_unit_status_get_sensor_rate_achieved(const mavlink_message_t* msg)
{
    return _MAV_RETURN_float(msg,  52);
}

/**
 * @brief Get field raw_rate_requested from kf_unit_status message
 *
 * @return [Hz] Requested KF_RAW_SAMPLE stream rate (0: off).
 */
static inline float mavlink_msg_kf_unit_status_get_raw_rate_requested(const mavlink_message_t* msg)
{
    return _MAV_RETURN_float(msg,  56);
}

/**
 * @brief Get field raw_rate_achieved from kf_unit_status message
 *
 * @return [Hz] KF_RAW_SAMPLE frames sent per second since the previous status.
 */
static inline float mavlink_msg_kf_unit_status_get_raw_rate_achieved(const mavlink_message_t* msg)
{
    return _MAV_RETURN_float(msg,  60);
}

/**
 * @brief Get field orientation_rate_requested from kf_unit_status message
 *
 * @return [Hz] Requested KF_ORIENTATION stream rate (0: off).
 */
static inline float mavlink_msg_kf_unit_status_get_orientation_rate_requested(const mavlink_message_t* msg)
{
    return _MAV_RETURN_float(msg,  64);
}

/**
 * @brief Get field orientation_rate_achieved from kf_unit_status message
 *
 * @return [Hz] KF_ORIENTATION frames sent per second since the previous status.
 */
static inline float mavlink_msg_kf_unit_status_get_orientation_rate_achieved(const mavlink_message_t* msg)
{
    return _MAV_RETURN_float(msg,  68);
}

/**
 * @brief Get field battery_voltage from kf_unit_status message
 *
 * @return [mV] Battery voltage (UINT16_MAX: unknown).
 */
static inline uint16_t mavlink_msg_kf_unit_status_get_battery_voltage(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint16_t(msg,  72);
}

/**
 * @brief Get field cpu_load from kf_unit_status message
 *
 * @return [d%] Processor load (0..1000).
 */
static inline uint16_t mavlink_msg_kf_unit_status_get_cpu_load(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint16_t(msg,  74);
}

/**
 * @brief Get field status_flags from kf_unit_status message
 *
 * @return  Status bits.
 */
static inline uint16_t mavlink_msg_kf_unit_status_get_status_flags(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint16_t(msg,  76);
}

/**
 * @brief Get field battery_remaining from kf_unit_status message
 *
 * @return [%] Remaining battery charge (-1: unknown).
 */
static inline int8_t mavlink_msg_kf_unit_status_get_battery_remaining(const mavlink_message_t* msg)
{
    return _MAV_RETURN_int8_t(msg,  78);
}

/**
 * @brief Get field unit_id from kf_unit_status message
 *
 * @return  Unit id.
 */
static inline uint8_t mavlink_msg_kf_unit_status_get_unit_id(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  79);
}

/**
 * @brief Get field filter_id from kf_unit_status message
 *
 * @return  Orientation estimator running.
 */
static inline uint8_t mavlink_msg_kf_unit_status_get_filter_id(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  80);
}

/**
 * @brief Get field numeric_format from kf_unit_status message
 *
 * @return  Arithmetic of the estimators.
 */
static inline uint8_t mavlink_msg_kf_unit_status_get_numeric_format(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  81);
}

/**
 * @brief Get field earth_frame from kf_unit_status message
 *
 * @return  Earth frame of KF_ORIENTATION.
 */
static inline uint8_t mavlink_msg_kf_unit_status_get_earth_frame(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  82);
}

/**
 * @brief Get field numeric_resets from kf_unit_status message
 *
 * @return  Orientation filter restarts after a non-finite state (either sensor's filter in two-sensor mode; each also sets NUMERIC_RESET in KF_ORIENTATION or KF_JOINT_ANGLE).
 */
static inline uint32_t mavlink_msg_kf_unit_status_get_numeric_resets(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  83);
}

/**
 * @brief Get field hil_invalid from kf_unit_status message
 *
 * @return  HIL_SENSOR messages not processed: a NaN acc/gyro/mag value, or a sensor id the unit does not have (id 1 without two-sensor mode, id > 1).
 */
static inline uint32_t mavlink_msg_kf_unit_status_get_hil_invalid(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  87);
}

/**
 * @brief Get field rejected_samples2 from kf_unit_status message
 *
 * @return  Samples rejected by sensor 1's orientation filter (two-sensor mode, KF_JOINT_ID != 0; rejected_samples is sensor 0's).
 */
static inline uint32_t mavlink_msg_kf_unit_status_get_rejected_samples2(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  91);
}

/**
 * @brief Decode a kf_unit_status message into a struct
 *
 * @param msg The message to decode
 * @param kf_unit_status C-struct to decode the message contents into
 */
static inline void mavlink_msg_kf_unit_status_decode(const mavlink_message_t* msg, mavlink_kf_unit_status_t* kf_unit_status)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    kf_unit_status->time_boot_us = mavlink_msg_kf_unit_status_get_time_boot_us(msg);
    kf_unit_status->firmware_version = mavlink_msg_kf_unit_status_get_firmware_version(msg);
    kf_unit_status->firmware_git_hash = mavlink_msg_kf_unit_status_get_firmware_git_hash(msg);
    kf_unit_status->dialect_hash = mavlink_msg_kf_unit_status_get_dialect_hash(msg);
    kf_unit_status->samples = mavlink_msg_kf_unit_status_get_samples(msg);
    kf_unit_status->samples_dropped = mavlink_msg_kf_unit_status_get_samples_dropped(msg);
    kf_unit_status->frames_dropped = mavlink_msg_kf_unit_status_get_frames_dropped(msg);
    kf_unit_status->rejected_samples = mavlink_msg_kf_unit_status_get_rejected_samples(msg);
    kf_unit_status->crc_errors = mavlink_msg_kf_unit_status_get_crc_errors(msg);
    kf_unit_status->unknown_messages = mavlink_msg_kf_unit_status_get_unknown_messages(msg);
    kf_unit_status->param_rejects = mavlink_msg_kf_unit_status_get_param_rejects(msg);
    kf_unit_status->sensor_rate_requested = mavlink_msg_kf_unit_status_get_sensor_rate_requested(msg);
    kf_unit_status->sensor_rate_achieved = mavlink_msg_kf_unit_status_get_sensor_rate_achieved(msg);
    kf_unit_status->raw_rate_requested = mavlink_msg_kf_unit_status_get_raw_rate_requested(msg);
    kf_unit_status->raw_rate_achieved = mavlink_msg_kf_unit_status_get_raw_rate_achieved(msg);
    kf_unit_status->orientation_rate_requested = mavlink_msg_kf_unit_status_get_orientation_rate_requested(msg);
    kf_unit_status->orientation_rate_achieved = mavlink_msg_kf_unit_status_get_orientation_rate_achieved(msg);
    kf_unit_status->battery_voltage = mavlink_msg_kf_unit_status_get_battery_voltage(msg);
    kf_unit_status->cpu_load = mavlink_msg_kf_unit_status_get_cpu_load(msg);
    kf_unit_status->status_flags = mavlink_msg_kf_unit_status_get_status_flags(msg);
    kf_unit_status->battery_remaining = mavlink_msg_kf_unit_status_get_battery_remaining(msg);
    kf_unit_status->unit_id = mavlink_msg_kf_unit_status_get_unit_id(msg);
    kf_unit_status->filter_id = mavlink_msg_kf_unit_status_get_filter_id(msg);
    kf_unit_status->numeric_format = mavlink_msg_kf_unit_status_get_numeric_format(msg);
    kf_unit_status->earth_frame = mavlink_msg_kf_unit_status_get_earth_frame(msg);
    kf_unit_status->numeric_resets = mavlink_msg_kf_unit_status_get_numeric_resets(msg);
    kf_unit_status->hil_invalid = mavlink_msg_kf_unit_status_get_hil_invalid(msg);
    kf_unit_status->rejected_samples2 = mavlink_msg_kf_unit_status_get_rejected_samples2(msg);
#else
        uint8_t len = msg->len < MAVLINK_MSG_ID_KF_UNIT_STATUS_LEN? msg->len : MAVLINK_MSG_ID_KF_UNIT_STATUS_LEN;
        memset(kf_unit_status, 0, MAVLINK_MSG_ID_KF_UNIT_STATUS_LEN);
    memcpy(kf_unit_status, _MAV_PAYLOAD(msg), len);
#endif
}
