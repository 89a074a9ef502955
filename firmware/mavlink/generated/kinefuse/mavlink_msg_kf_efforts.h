#pragma once
// MESSAGE KF_EFFORTS PACKING

#include <stdint.h>

#define MAVLINK_MSG_ID_KF_EFFORTS 52503


typedef struct __mavlink_kf_efforts_t {
 uint64_t time_boot_us; /*< [us] Time of the newest sample used, unit clock, microseconds since boot.*/
 uint32_t sample_counter; /*<  sample_counter of the newest sample used.*/
 float effort[12]; /*<  Effort estimates, N or N*m per model_id.*/
 float effort_std[12]; /*<  Standard deviations of the effort estimates (square root of the filter covariance diagonal), same units as effort.*/
 uint8_t model_id; /*<  Dynamic model.*/
 uint8_t count; /*<  Number of valid entries in effort and effort_std (0..12).*/
 uint8_t status; /*<  Status bits.*/
} mavlink_kf_efforts_t;

#define MAVLINK_MSG_ID_KF_EFFORTS_LEN 111
#define MAVLINK_MSG_ID_KF_EFFORTS_MIN_LEN 111
#define MAVLINK_MSG_ID_52503_LEN 111
#define MAVLINK_MSG_ID_52503_MIN_LEN 111

#define MAVLINK_MSG_ID_KF_EFFORTS_CRC 9
#define MAVLINK_MSG_ID_52503_CRC 9

#define MAVLINK_MSG_KF_EFFORTS_FIELD_EFFORT_LEN 12
#define MAVLINK_MSG_KF_EFFORTS_FIELD_EFFORT_STD_LEN 12

#if MAVLINK_COMMAND_24BIT
#define MAVLINK_MESSAGE_INFO_KF_EFFORTS { \
    52503, \
    "KF_EFFORTS", \
    7, \
    {  { "time_boot_us", NULL, MAVLINK_TYPE_UINT64_T, 0, 0, offsetof(mavlink_kf_efforts_t, time_boot_us) }, \
         { "sample_counter", NULL, MAVLINK_TYPE_UINT32_T, 0, 8, offsetof(mavlink_kf_efforts_t, sample_counter) }, \
         { "effort", NULL, MAVLINK_TYPE_FLOAT, 12, 12, offsetof(mavlink_kf_efforts_t, effort) }, \
         { "effort_std", NULL, MAVLINK_TYPE_FLOAT, 12, 60, offsetof(mavlink_kf_efforts_t, effort_std) }, \
         { "model_id", NULL, MAVLINK_TYPE_UINT8_T, 0, 108, offsetof(mavlink_kf_efforts_t, model_id) }, \
         { "count", NULL, MAVLINK_TYPE_UINT8_T, 0, 109, offsetof(mavlink_kf_efforts_t, count) }, \
         { "status", NULL, MAVLINK_TYPE_UINT8_T, 0, 110, offsetof(mavlink_kf_efforts_t, status) }, \
         } \
}
#else
#define MAVLINK_MESSAGE_INFO_KF_EFFORTS { \
    "KF_EFFORTS", \
    7, \
    {  { "time_boot_us", NULL, MAVLINK_TYPE_UINT64_T, 0, 0, offsetof(mavlink_kf_efforts_t, time_boot_us) }, \
         { "sample_counter", NULL, MAVLINK_TYPE_UINT32_T, 0, 8, offsetof(mavlink_kf_efforts_t, sample_counter) }, \
         { "effort", NULL, MAVLINK_TYPE_FLOAT, 12, 12, offsetof(mavlink_kf_efforts_t, effort) }, \
         { "effort_std", NULL, MAVLINK_TYPE_FLOAT, 12, 60, offsetof(mavlink_kf_efforts_t, effort_std) }, \
         { "model_id", NULL, MAVLINK_TYPE_UINT8_T, 0, 108, offsetof(mavlink_kf_efforts_t, model_id) }, \
         { "count", NULL, MAVLINK_TYPE_UINT8_T, 0, 109, offsetof(mavlink_kf_efforts_t, count) }, \
         { "status", NULL, MAVLINK_TYPE_UINT8_T, 0, 110, offsetof(mavlink_kf_efforts_t, status) }, \
         } \
}
#endif

/**
 * @brief Pack a kf_efforts message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 *
 * @param time_boot_us [us] Time of the newest sample used, unit clock, microseconds since boot.
 * @param sample_counter  sample_counter of the newest sample used.
 * @param effort  Effort estimates, N or N*m per model_id.
 * @param effort_std  Standard deviations of the effort estimates (square root of the filter covariance diagonal), same units as effort.
 * @param model_id  Dynamic model.
 * @param count  Number of valid entries in effort and effort_std (0..12).
 * @param status  Status bits.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_kf_efforts_pack(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg,
                               uint64_t time_boot_us, uint32_t sample_counter, const float *effort, const float *effort_std, uint8_t model_id, uint8_t count, uint8_t status)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_KF_EFFORTS_LEN];
    _mav_put_uint64_t(buf, 0, time_boot_us);
    _mav_put_uint32_t(buf, 8, sample_counter);
    _mav_put_uint8_t(buf, 108, model_id);
    _mav_put_uint8_t(buf, 109, count);
    _mav_put_uint8_t(buf, 110, status);
    _mav_put_float_array(buf, 12, effort, 12);
    _mav_put_float_array(buf, 60, effort_std, 12);
        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_KF_EFFORTS_LEN);
#else
    mavlink_kf_efforts_t packet;
    packet.time_boot_us = time_boot_us;
    packet.sample_counter = sample_counter;
    packet.model_id = model_id;
    packet.count = count;
    packet.status = status;
    mav_array_memcpy(packet.effort, effort, sizeof(float)*12);
    mav_array_memcpy(packet.effort_std, effort_std, sizeof(float)*12);
        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_KF_EFFORTS_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_KF_EFFORTS;
    return mavlink_finalize_message(msg, system_id, component_id, MAVLINK_MSG_ID_KF_EFFORTS_MIN_LEN, MAVLINK_MSG_ID_KF_EFFORTS_LEN, MAVLINK_MSG_ID_KF_EFFORTS_CRC);
}

/**
 * @brief Pack a kf_efforts message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 *
 * @param time_boot_us [us] Time of the newest sample used, unit clock, microseconds since boot.
 * @param sample_counter  sample_counter of the newest sample used.
 * @param effort  Effort estimates, N or N*m per model_id.
 * @param effort_std  Standard deviations of the effort estimates (square root of the filter covariance diagonal), same units as effort.
 * @param model_id  Dynamic model.
 * @param count  Number of valid entries in effort and effort_std (0..12).
 * @param status  Status bits.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_kf_efforts_pack_status(uint8_t system_id, uint8_t component_id, mavlink_status_t *_status, mavlink_message_t* msg,
                               uint64_t time_boot_us, uint32_t sample_counter, const float *effort, const float *effort_std, uint8_t model_id, uint8_t count, uint8_t status)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_KF_EFFORTS_LEN];
    _mav_put_uint64_t(buf, 0, time_boot_us);
    _mav_put_uint32_t(buf, 8, sample_counter);
    _mav_put_uint8_t(buf, 108, model_id);
    _mav_put_uint8_t(buf, 109, count);
    _mav_put_uint8_t(buf, 110, status);
    _mav_put_float_array(buf, 12, effort, 12);
    _mav_put_float_array(buf, 60, effort_std, 12);
        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_KF_EFFORTS_LEN);
#else
    mavlink_kf_efforts_t packet;
    packet.time_boot_us = time_boot_us;
    packet.sample_counter = sample_counter;
    packet.model_id = model_id;
    packet.count = count;
    packet.status = status;
    mav_array_memcpy(packet.effort, effort, sizeof(float)*12);
    mav_array_memcpy(packet.effort_std, effort_std, sizeof(float)*12);
        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_KF_EFFORTS_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_KF_EFFORTS;
#if MAVLINK_CRC_EXTRA
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_KF_EFFORTS_MIN_LEN, MAVLINK_MSG_ID_KF_EFFORTS_LEN, MAVLINK_MSG_ID_KF_EFFORTS_CRC);
#else
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_KF_EFFORTS_MIN_LEN, MAVLINK_MSG_ID_KF_EFFORTS_LEN);
#endif
}

/**
 * @brief Pack a kf_efforts message on a channel
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param time_boot_us [us] Time of the newest sample used, unit clock, microseconds since boot.
 * @param sample_counter  sample_counter of the newest sample used.
 * @param effort  Effort estimates, N or N*m per model_id.
 * @param effort_std  Standard deviations of the effort estimates (square root of the filter covariance diagonal), same units as effort.
 * @param model_id  Dynamic model.
 * @param count  Number of valid entries in effort and effort_std (0..12).
 * @param status  Status bits.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_kf_efforts_pack_chan(uint8_t system_id, uint8_t component_id, uint8_t chan,
                               mavlink_message_t* msg,
                                   uint64_t time_boot_us,uint32_t sample_counter,const float *effort,const float *effort_std,uint8_t model_id,uint8_t count,uint8_t status)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_KF_EFFORTS_LEN];
    _mav_put_uint64_t(buf, 0, time_boot_us);
    _mav_put_uint32_t(buf, 8, sample_counter);
    _mav_put_uint8_t(buf, 108, model_id);
    _mav_put_uint8_t(buf, 109, count);
    _mav_put_uint8_t(buf, 110, status);
    _mav_put_float_array(buf, 12, effort, 12);
    _mav_put_float_array(buf, 60, effort_std, 12);
        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_KF_EFFORTS_LEN);
#else
    mavlink_kf_efforts_t packet;
    packet.time_boot_us = time_boot_us;
    packet.sample_counter = sample_counter;
    packet.model_id = model_id;
    packet.count = count;
    packet.status = status;
    mav_array_memcpy(packet.effort, effort, sizeof(float)*12);
    mav_array_memcpy(packet.effort_std, effort_std, sizeof(float)*12);
        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_KF_EFFORTS_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_KF_EFFORTS;
    return mavlink_finalize_message_chan(msg, system_id, component_id, chan, MAVLINK_MSG_ID_KF_EFFORTS_MIN_LEN, MAVLINK_MSG_ID_KF_EFFORTS_LEN, MAVLINK_MSG_ID_KF_EFFORTS_CRC);
}

/**
 * @brief Encode a kf_efforts struct
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 * @param kf_efforts C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_kf_efforts_encode(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg, const mavlink_kf_efforts_t* kf_efforts)
{
    return mavlink_msg_kf_efforts_pack(system_id, component_id, msg, kf_efforts->time_boot_us, kf_efforts->sample_counter, kf_efforts->effort, kf_efforts->effort_std, kf_efforts->model_id, kf_efforts->count, kf_efforts->status);
}

/**
 * @brief Encode a kf_efforts struct on a channel
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param kf_efforts C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_kf_efforts_encode_chan(uint8_t system_id, uint8_t component_id, uint8_t chan, mavlink_message_t* msg, const mavlink_kf_efforts_t* kf_efforts)
{
    return mavlink_msg_kf_efforts_pack_chan(system_id, component_id, chan, msg, kf_efforts->time_boot_us, kf_efforts->sample_counter, kf_efforts->effort, kf_efforts->effort_std, kf_efforts->model_id, kf_efforts->count, kf_efforts->status);
}

/**
 * @brief Encode a kf_efforts struct with provided status structure
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 * @param kf_efforts C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_kf_efforts_encode_status(uint8_t system_id, uint8_t component_id, mavlink_status_t* _status, mavlink_message_t* msg, const mavlink_kf_efforts_t* kf_efforts)
{
    return mavlink_msg_kf_efforts_pack_status(system_id, component_id, _status, msg,  kf_efforts->time_boot_us, kf_efforts->sample_counter, kf_efforts->effort, kf_efforts->effort_std, kf_efforts->model_id, kf_efforts->count, kf_efforts->status);
}

/**
 * @brief Send a kf_efforts message
 * @param chan MAVLink channel to send the message
 *
 * @param time_boot_us [us] Time of the newest sample used, unit clock, microseconds since boot.
 * @param sample_counter  sample_counter of the newest sample used.
 * @param effort  Effort estimates, N or N*m per model_id.
 * @param effort_std  Standard deviations of the effort estimates (square root of the filter covariance diagonal), same units as effort.
 * @param model_id  Dynamic model.
 * @param count  Number of valid entries in effort and effort_std (0..12).
 * @param status  Status bits.
 */
#ifdef MAVLINK_USE_CONVENIENCE_FUNCTIONS

static inline void mavlink_msg_kf_efforts_send(mavlink_channel_t chan, uint64_t time_boot_us, uint32_t sample_counter, const float *effort, const float *effort_std, uint8_t model_id, uint8_t count, uint8_t status)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_KF_EFFORTS_LEN];
    _mav_put_uint64_t(buf, 0, time_boot_us);
    _mav_put_uint32_t(buf, 8, sample_counter);
    _mav_put_uint8_t(buf, 108, model_id);
    _mav_put_uint8_t(buf, 109, count);
    _mav_put_uint8_t(buf, 110, status);
    _mav_put_float_array(buf, 12, effort, 12);
    _mav_put_float_array(buf, 60, effort_std, 12);
    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_KF_EFFORTS, buf, MAVLINK_MSG_ID_KF_EFFORTS_MIN_LEN, MAVLINK_MSG_ID_KF_EFFORTS_LEN, MAVLINK_MSG_ID_KF_EFFORTS_CRC);
#else
    mavlink_kf_efforts_t packet;
    packet.time_boot_us = time_boot_us;
    packet.sample_counter = sample_counter;
    packet.model_id = model_id;
    packet.count = count;
    packet.status = status;
    mav_array_memcpy(packet.effort, effort, sizeof(float)*12);
    mav_array_memcpy(packet.effort_std, effort_std, sizeof(float)*12);
    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_KF_EFFORTS, (const char *)&packet, MAVLINK_MSG_ID_KF_EFFORTS_MIN_LEN, MAVLINK_MSG_ID_KF_EFFORTS_LEN, MAVLINK_MSG_ID_KF_EFFORTS_CRC);
#endif
}

/**
 * @brief Send a kf_efforts message
 * @param chan MAVLink channel to send the message
 * @param struct The MAVLink struct to serialize
 */
static inline void mavlink_msg_kf_efforts_send_struct(mavlink_channel_t chan, const mavlink_kf_efforts_t* kf_efforts)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    mavlink_msg_kf_efforts_send(chan, kf_efforts->time_boot_us, kf_efforts->sample_counter, kf_efforts->effort, kf_efforts->effort_std, kf_efforts->model_id, kf_efforts->count, kf_efforts->status);
#else
    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_KF_EFFORTS, (const char *)kf_efforts, MAVLINK_MSG_ID_KF_EFFORTS_MIN_LEN, MAVLINK_MSG_ID_KF_EFFORTS_LEN, MAVLINK_MSG_ID_KF_EFFORTS_CRC);
#endif
}

#if MAVLINK_MSG_ID_KF_EFFORTS_LEN <= MAVLINK_MAX_PAYLOAD_LEN
/*
  This variant of _send() can be used to save stack space by reusing
  memory from the receive buffer.  The caller provides a
  mavlink_message_t which is the size of a full mavlink message. This
  is usually the receive buffer for the channel, and allows a reply to an
  incoming message with minimum stack space usage.
 */
static inline void mavlink_msg_kf_efforts_send_buf(mavlink_message_t *msgbuf, mavlink_channel_t chan,  uint64_t time_boot_us, uint32_t sample_counter, const float *effort, const float *effort_std, uint8_t model_id, uint8_t count, uint8_t status)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char *buf = (char *)msgbuf;
    _mav_put_uint64_t(buf, 0, time_boot_us);
    _mav_put_uint32_t(buf, 8, sample_counter);
    _mav_put_uint8_t(buf, 108, model_id);
    _mav_put_uint8_t(buf, 109, count);
    _mav_put_uint8_t(buf, 110, status);
    _mav_put_float_array(buf, 12, effort, 12);
    _mav_put_float_array(buf, 60, effort_std, 12);
    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_KF_EFFORTS, buf, MAVLINK_MSG_ID_KF_EFFORTS_MIN_LEN, MAVLINK_MSG_ID_KF_EFFORTS_LEN, MAVLINK_MSG_ID_KF_EFFORTS_CRC);
#else
    mavlink_kf_efforts_t *packet = (mavlink_kf_efforts_t *)msgbuf;
    packet->time_boot_us = time_boot_us;
    packet->sample_counter = sample_counter;
    packet->model_id = model_id;
    packet->count = count;
    packet->status = status;
    mav_array_memcpy(packet->effort, effort, sizeof(float)*12);
    mav_array_memcpy(packet->effort_std, effort_std, sizeof(float)*12);
    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_KF_EFFORTS, (const char *)packet, MAVLINK_MSG_ID_KF_EFFORTS_MIN_LEN, MAVLINK_MSG_ID_KF_EFFORTS_LEN, MAVLINK_MSG_ID_KF_EFFORTS_CRC);
#endif
}
#endif

#endif

// MESSAGE KF_EFFORTS UNPACKING


/**
 * @brief Get field time_boot_us from kf_efforts message
 *
 * @return [us] Time of the newest sample used, unit clock, microseconds since boot.
 */
static inline uint64_t mavlink_msg_kf_efforts_get_time_boot_us(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint64_t(msg,  0);
}

/**
 * @brief Get field sample_counter from kf_efforts message
 *
 * @return  sample_counter of the newest sample used.
 */
static inline uint32_t mavlink_msg_kf_efforts_get_sample_counter(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  8);
}

/**
 * @brief Get field effort from kf_efforts message
 *
 * @return  Effort estimates, N or N*m per model_id.
 */
static inline uint16_t mavlink_msg_kf_efforts_get_effort(const mavlink_message_t* msg, float *effort)
{
    return _MAV_RETURN_float_array(msg, effort, 12,  12);
}

/**
 * @brief Get field effort_std from kf_efforts message
 *
 * @return  Standard deviations of the effort estimates (square root of the filter covariance diagonal), same units as effort.
 */
static inline uint16_t mavlink_msg_kf_efforts_get_effort_std(const mavlink_message_t* msg, float *effort_std)
{
    return _MAV_RETURN_float_array(msg, effort_std, 12,  60);
}

/**
 * @brief Get field model_id from kf_efforts message
 *
 * @return  Dynamic model.
 */
static inline uint8_t mavlink_msg_kf_efforts_get_model_id(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  108);
}

/**
 * @brief Get field count from kf_efforts message
 *
 * @return  Number of valid entries in effort and effort_std (0..12).
 */
static inline uint8_t mavlink_msg_kf_efforts_get_count(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  109);
}

/**
 * @brief Get field status from kf_efforts message
 *
 * @return  Status bits.
 */
static inline uint8_t mavlink_msg_kf_efforts_get_status(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  110);
}

/**
 * @brief Decode a kf_efforts message into a struct
 *
 * @param msg The message to decode
 * @param kf_efforts C-struct to decode the message contents into
 */
static inline void mavlink_msg_kf_efforts_decode(const mavlink_message_t* msg, mavlink_kf_efforts_t* kf_efforts)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    kf_efforts->time_boot_us = mavlink_msg_kf_efforts_get_time_boot_us(msg);
    kf_efforts->sample_counter = mavlink_msg_kf_efforts_get_sample_counter(msg);
    mavlink_msg_kf_efforts_get_effort(msg, kf_efforts->effort);
    mavlink_msg_kf_efforts_get_effort_std(msg, kf_efforts->effort_std);
    kf_efforts->model_id = mavlink_msg_kf_efforts_get_model_id(msg);
    kf_efforts->count = mavlink_msg_kf_efforts_get_count(msg);
    kf_efforts->status = mavlink_msg_kf_efforts_get_status(msg);
#else
        uint8_t len = msg->len < MAVLINK_MSG_ID_KF_EFFORTS_LEN? msg->len : MAVLINK_MSG_ID_KF_EFFORTS_LEN;
        memset(kf_efforts, 0, MAVLINK_MSG_ID_KF_EFFORTS_LEN);
    memcpy(kf_efforts, _MAV_PAYLOAD(msg), len);
#endif
}
