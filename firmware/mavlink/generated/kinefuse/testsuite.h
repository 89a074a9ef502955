/** @file
 *    @brief MAVLink comm protocol testsuite generated from kinefuse.xml
 *    @see https://mavlink.io/en/
 */
#pragma once
#ifndef KINEFUSE_TESTSUITE_H
#define KINEFUSE_TESTSUITE_H

#ifdef __cplusplus
extern "C" {
#endif

#ifndef MAVLINK_TEST_ALL
#define MAVLINK_TEST_ALL
static void mavlink_test_common(uint8_t, uint8_t, mavlink_message_t *last_msg);
static void mavlink_test_kinefuse(uint8_t, uint8_t, mavlink_message_t *last_msg);

static void mavlink_test_all(uint8_t system_id, uint8_t component_id, mavlink_message_t *last_msg)
{
    mavlink_test_common(system_id, component_id, last_msg);
    mavlink_test_kinefuse(system_id, component_id, last_msg);
}
#endif

#include "../common/testsuite.h"


static void mavlink_test_kf_raw_sample(uint8_t system_id, uint8_t component_id, mavlink_message_t *last_msg)
{
#ifdef MAVLINK_STATUS_FLAG_OUT_MAVLINK1
    mavlink_status_t *status = mavlink_get_channel_status(MAVLINK_COMM_0);
        if ((status->flags & MAVLINK_STATUS_FLAG_OUT_MAVLINK1) && MAVLINK_MSG_ID_KF_RAW_SAMPLE >= 256) {
            return;
        }
#endif
    mavlink_message_t msg;
        uint8_t buffer[MAVLINK_MAX_PACKET_LEN];
        uint16_t i;
    mavlink_kf_raw_sample_t packet_in = {
        93372036854775807ULL,963497880,17859,17963,18067,18171,18275,18379,18483,18587,18691,18795,101,168,235
    };
    mavlink_kf_raw_sample_t packet1, packet2;
        memset(&packet1, 0, sizeof(packet1));
        packet1.time_boot_us = packet_in.time_boot_us;
        packet1.sample_counter = packet_in.sample_counter;
        packet1.acc_x = packet_in.acc_x;
        packet1.acc_y = packet_in.acc_y;
        packet1.acc_z = packet_in.acc_z;
        packet1.gyro_x = packet_in.gyro_x;
        packet1.gyro_y = packet_in.gyro_y;
        packet1.gyro_z = packet_in.gyro_z;
        packet1.mag_x = packet_in.mag_x;
        packet1.mag_y = packet_in.mag_y;
        packet1.mag_z = packet_in.mag_z;
        packet1.temperature = packet_in.temperature;
        packet1.unit_id = packet_in.unit_id;
        packet1.flags = packet_in.flags;
        packet1.gyro_shift = packet_in.gyro_shift;
        
        
#ifdef MAVLINK_STATUS_FLAG_OUT_MAVLINK1
        if (status->flags & MAVLINK_STATUS_FLAG_OUT_MAVLINK1) {
           // cope with extensions
           memset(MAVLINK_MSG_ID_KF_RAW_SAMPLE_MIN_LEN + (char *)&packet1, 0, sizeof(packet1)-MAVLINK_MSG_ID_KF_RAW_SAMPLE_MIN_LEN);
        }
#endif
        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_kf_raw_sample_encode(system_id, component_id, &msg, &packet1);
    mavlink_msg_kf_raw_sample_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_kf_raw_sample_pack(system_id, component_id, &msg , packet1.time_boot_us , packet1.sample_counter , packet1.acc_x , packet1.acc_y , packet1.acc_z , packet1.gyro_x , packet1.gyro_y , packet1.gyro_z , packet1.mag_x , packet1.mag_y , packet1.mag_z , packet1.temperature , packet1.unit_id , packet1.flags , packet1.gyro_shift );
    mavlink_msg_kf_raw_sample_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_kf_raw_sample_pack_chan(system_id, component_id, MAVLINK_COMM_0, &msg , packet1.time_boot_us , packet1.sample_counter , packet1.acc_x , packet1.acc_y , packet1.acc_z , packet1.gyro_x , packet1.gyro_y , packet1.gyro_z , packet1.mag_x , packet1.mag_y , packet1.mag_z , packet1.temperature , packet1.unit_id , packet1.flags , packet1.gyro_shift );
    mavlink_msg_kf_raw_sample_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
        mavlink_msg_to_send_buffer(buffer, &msg);
        for (i=0; i<mavlink_msg_get_send_buffer_length(&msg); i++) {
            comm_send_ch(MAVLINK_COMM_0, buffer[i]);
        }
    mavlink_msg_kf_raw_sample_decode(last_msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);
        
        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_kf_raw_sample_send(MAVLINK_COMM_1 , packet1.time_boot_us , packet1.sample_counter , packet1.acc_x , packet1.acc_y , packet1.acc_z , packet1.gyro_x , packet1.gyro_y , packet1.gyro_z , packet1.mag_x , packet1.mag_y , packet1.mag_z , packet1.temperature , packet1.unit_id , packet1.flags , packet1.gyro_shift );
    mavlink_msg_kf_raw_sample_decode(last_msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

#ifdef MAVLINK_HAVE_GET_MESSAGE_INFO
    MAVLINK_ASSERT(mavlink_get_message_info_by_name("KF_RAW_SAMPLE") != NULL);
    MAVLINK_ASSERT(mavlink_get_message_info_by_id(MAVLINK_MSG_ID_KF_RAW_SAMPLE) != NULL);
#endif
}

static void mavlink_test_kf_orientation(uint8_t system_id, uint8_t component_id, mavlink_message_t *last_msg)
{
#ifdef MAVLINK_STATUS_FLAG_OUT_MAVLINK1
    mavlink_status_t *status = mavlink_get_channel_status(MAVLINK_COMM_0);
        if ((status->flags & MAVLINK_STATUS_FLAG_OUT_MAVLINK1) && MAVLINK_MSG_ID_KF_ORIENTATION >= 256) {
            return;
        }
#endif
    mavlink_message_t msg;
        uint8_t buffer[MAVLINK_MAX_PACKET_LEN];
        uint16_t i;
    mavlink_kf_orientation_t packet_in = {
        93372036854775807ULL,963497880,101.0,129.0,157.0,185.0,963498920,18899,235,46,113,{ 276.0, 277.0, 278.0, 279.0, 280.0, 281.0 }
    };
    mavlink_kf_orientation_t packet1, packet2;
        memset(&packet1, 0, sizeof(packet1));
        packet1.time_boot_us = packet_in.time_boot_us;
        packet1.sample_counter = packet_in.sample_counter;
        packet1.q_w = packet_in.q_w;
        packet1.q_x = packet_in.q_x;
        packet1.q_y = packet_in.q_y;
        packet1.q_z = packet_in.q_z;
        packet1.rejected_samples = packet_in.rejected_samples;
        packet1.status = packet_in.status;
        packet1.earth_frame = packet_in.earth_frame;
        packet1.filter_id = packet_in.filter_id;
        packet1.unit_id = packet_in.unit_id;
        
        mav_array_memcpy(packet1.cov, packet_in.cov, sizeof(float)*6);
        
#ifdef MAVLINK_STATUS_FLAG_OUT_MAVLINK1
        if (status->flags & MAVLINK_STATUS_FLAG_OUT_MAVLINK1) {
           // cope with extensions
           memset(MAVLINK_MSG_ID_KF_ORIENTATION_MIN_LEN + (char *)&packet1, 0, sizeof(packet1)-MAVLINK_MSG_ID_KF_ORIENTATION_MIN_LEN);
        }
#endif
        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_kf_orientation_encode(system_id, component_id, &msg, &packet1);
    mavlink_msg_kf_orientation_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_kf_orientation_pack(system_id, component_id, &msg , packet1.time_boot_us , packet1.sample_counter , packet1.q_w , packet1.q_x , packet1.q_y , packet1.q_z , packet1.rejected_samples , packet1.status , packet1.earth_frame , packet1.filter_id , packet1.unit_id , packet1.cov );
    mavlink_msg_kf_orientation_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_kf_orientation_pack_chan(system_id, component_id, MAVLINK_COMM_0, &msg , packet1.time_boot_us , packet1.sample_counter , packet1.q_w , packet1.q_x , packet1.q_y , packet1.q_z , packet1.rejected_samples , packet1.status , packet1.earth_frame , packet1.filter_id , packet1.unit_id , packet1.cov );
    mavlink_msg_kf_orientation_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
        mavlink_msg_to_send_buffer(buffer, &msg);
        for (i=0; i<mavlink_msg_get_send_buffer_length(&msg); i++) {
            comm_send_ch(MAVLINK_COMM_0, buffer[i]);
        }
    mavlink_msg_kf_orientation_decode(last_msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);
        
        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_kf_orientation_send(MAVLINK_COMM_1 , packet1.time_boot_us , packet1.sample_counter , packet1.q_w , packet1.q_x , packet1.q_y , packet1.q_z , packet1.rejected_samples , packet1.status , packet1.earth_frame , packet1.filter_id , packet1.unit_id , packet1.cov );
    mavlink_msg_kf_orientation_decode(last_msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

#ifdef MAVLINK_HAVE_GET_MESSAGE_INFO
    MAVLINK_ASSERT(mavlink_get_message_info_by_name("KF_ORIENTATION") != NULL);
    MAVLINK_ASSERT(mavlink_get_message_info_by_id(MAVLINK_MSG_ID_KF_ORIENTATION) != NULL);
#endif
}

static void mavlink_test_kf_joint_angle(uint8_t system_id, uint8_t component_id, mavlink_message_t *last_msg)
{
#ifdef MAVLINK_STATUS_FLAG_OUT_MAVLINK1
    mavlink_status_t *status = mavlink_get_channel_status(MAVLINK_COMM_0);
        if ((status->flags & MAVLINK_STATUS_FLAG_OUT_MAVLINK1) && MAVLINK_MSG_ID_KF_JOINT_ANGLE >= 256) {
            return;
        }
#endif
    mavlink_message_t msg;
        uint8_t buffer[MAVLINK_MAX_PACKET_LEN];
        uint16_t i;
    mavlink_kf_joint_angle_t packet_in = {
        93372036854775807ULL,963497880,101.0,129.0,157.0,77,144,211,22,89
    };
    mavlink_kf_joint_angle_t packet1, packet2;
        memset(&packet1, 0, sizeof(packet1));
        packet1.time_boot_us = packet_in.time_boot_us;
        packet1.sample_counter = packet_in.sample_counter;
        packet1.angle_1 = packet_in.angle_1;
        packet1.angle_2 = packet_in.angle_2;
        packet1.angle_3 = packet_in.angle_3;
        packet1.joint_id = packet_in.joint_id;
        packet1.sequence = packet_in.sequence;
        packet1.status = packet_in.status;
        packet1.proximal_unit = packet_in.proximal_unit;
        packet1.distal_unit = packet_in.distal_unit;
        
        
#ifdef MAVLINK_STATUS_FLAG_OUT_MAVLINK1
        if (status->flags & MAVLINK_STATUS_FLAG_OUT_MAVLINK1) {
           // cope with extensions
           memset(MAVLINK_MSG_ID_KF_JOINT_ANGLE_MIN_LEN + (char *)&packet1, 0, sizeof(packet1)-MAVLINK_MSG_ID_KF_JOINT_ANGLE_MIN_LEN);
        }
#endif
        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_kf_joint_angle_encode(system_id, component_id, &msg, &packet1);
    mavlink_msg_kf_joint_angle_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_kf_joint_angle_pack(system_id, component_id, &msg , packet1.time_boot_us , packet1.sample_counter , packet1.angle_1 , packet1.angle_2 , packet1.angle_3 , packet1.joint_id , packet1.sequence , packet1.status , packet1.proximal_unit , packet1.distal_unit );
    mavlink_msg_kf_joint_angle_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_kf_joint_angle_pack_chan(system_id, component_id, MAVLINK_COMM_0, &msg , packet1.time_boot_us , packet1.sample_counter , packet1.angle_1 , packet1.angle_2 , packet1.angle_3 , packet1.joint_id , packet1.sequence , packet1.status , packet1.proximal_unit , packet1.distal_unit );
    mavlink_msg_kf_joint_angle_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
        mavlink_msg_to_send_buffer(buffer, &msg);
        for (i=0; i<mavlink_msg_get_send_buffer_length(&msg); i++) {
            comm_send_ch(MAVLINK_COMM_0, buffer[i]);
        }
    mavlink_msg_kf_joint_angle_decode(last_msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);
        
        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_kf_joint_angle_send(MAVLINK_COMM_1 , packet1.time_boot_us , packet1.sample_counter , packet1.angle_1 , packet1.angle_2 , packet1.angle_3 , packet1.joint_id , packet1.sequence , packet1.status , packet1.proximal_unit , packet1.distal_unit );
    mavlink_msg_kf_joint_angle_decode(last_msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

#ifdef MAVLINK_HAVE_GET_MESSAGE_INFO
    MAVLINK_ASSERT(mavlink_get_message_info_by_name("KF_JOINT_ANGLE") != NULL);
    MAVLINK_ASSERT(mavlink_get_message_info_by_id(MAVLINK_MSG_ID_KF_JOINT_ANGLE) != NULL);
#endif
}

static void mavlink_test_kf_efforts(uint8_t system_id, uint8_t component_id, mavlink_message_t *last_msg)
{
#ifdef MAVLINK_STATUS_FLAG_OUT_MAVLINK1
    mavlink_status_t *status = mavlink_get_channel_status(MAVLINK_COMM_0);
        if ((status->flags & MAVLINK_STATUS_FLAG_OUT_MAVLINK1) && MAVLINK_MSG_ID_KF_EFFORTS >= 256) {
            return;
        }
#endif
    mavlink_message_t msg;
        uint8_t buffer[MAVLINK_MAX_PACKET_LEN];
        uint16_t i;
    mavlink_kf_efforts_t packet_in = {
        93372036854775807ULL,963497880,{ 101.0, 102.0, 103.0, 104.0, 105.0, 106.0, 107.0, 108.0, 109.0, 110.0, 111.0, 112.0 },{ 437.0, 438.0, 439.0, 440.0, 441.0, 442.0, 443.0, 444.0, 445.0, 446.0, 447.0, 448.0 },73,140,207
    };
    mavlink_kf_efforts_t packet1, packet2;
        memset(&packet1, 0, sizeof(packet1));
        packet1.time_boot_us = packet_in.time_boot_us;
        packet1.sample_counter = packet_in.sample_counter;
        packet1.model_id = packet_in.model_id;
        packet1.count = packet_in.count;
        packet1.status = packet_in.status;
        
        mav_array_memcpy(packet1.effort, packet_in.effort, sizeof(float)*12);
        mav_array_memcpy(packet1.effort_std, packet_in.effort_std, sizeof(float)*12);
        
#ifdef MAVLINK_STATUS_FLAG_OUT_MAVLINK1
        if (status->flags & MAVLINK_STATUS_FLAG_OUT_MAVLINK1) {
           // cope with extensions
           memset(MAVLINK_MSG_ID_KF_EFFORTS_MIN_LEN + (char *)&packet1, 0, sizeof(packet1)-MAVLINK_MSG_ID_KF_EFFORTS_MIN_LEN);
        }
#endif
        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_kf_efforts_encode(system_id, component_id, &msg, &packet1);
    mavlink_msg_kf_efforts_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_kf_efforts_pack(system_id, component_id, &msg , packet1.time_boot_us , packet1.sample_counter , packet1.effort , packet1.effort_std , packet1.model_id , packet1.count , packet1.status );
    mavlink_msg_kf_efforts_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_kf_efforts_pack_chan(system_id, component_id, MAVLINK_COMM_0, &msg , packet1.time_boot_us , packet1.sample_counter , packet1.effort , packet1.effort_std , packet1.model_id , packet1.count , packet1.status );
    mavlink_msg_kf_efforts_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
        mavlink_msg_to_send_buffer(buffer, &msg);
        for (i=0; i<mavlink_msg_get_send_buffer_length(&msg); i++) {
            comm_send_ch(MAVLINK_COMM_0, buffer[i]);
        }
    mavlink_msg_kf_efforts_decode(last_msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);
        
        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_kf_efforts_send(MAVLINK_COMM_1 , packet1.time_boot_us , packet1.sample_counter , packet1.effort , packet1.effort_std , packet1.model_id , packet1.count , packet1.status );
    mavlink_msg_kf_efforts_decode(last_msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

#ifdef MAVLINK_HAVE_GET_MESSAGE_INFO
    MAVLINK_ASSERT(mavlink_get_message_info_by_name("KF_EFFORTS") != NULL);
    MAVLINK_ASSERT(mavlink_get_message_info_by_id(MAVLINK_MSG_ID_KF_EFFORTS) != NULL);
#endif
}

static void mavlink_test_kf_unit_status(uint8_t system_id, uint8_t component_id, mavlink_message_t *last_msg)
{
#ifdef MAVLINK_STATUS_FLAG_OUT_MAVLINK1
    mavlink_status_t *status = mavlink_get_channel_status(MAVLINK_COMM_0);
        if ((status->flags & MAVLINK_STATUS_FLAG_OUT_MAVLINK1) && MAVLINK_MSG_ID_KF_UNIT_STATUS >= 256) {
            return;
        }
#endif
    mavlink_message_t msg;
        uint8_t buffer[MAVLINK_MAX_PACKET_LEN];
        uint16_t i;
    mavlink_kf_unit_status_t packet_in = {
        93372036854775807ULL,963497880,963498088,963498296,963498504,963498712,963498920,963499128,963499336,963499544,963499752,353.0,381.0,409.0,437.0,465.0,493.0,20979,21083,21187,111,178,245,56,123,963501780,963501988,963502196
    };
    mavlink_kf_unit_status_t packet1, packet2;
        memset(&packet1, 0, sizeof(packet1));
        packet1.time_boot_us = packet_in.time_boot_us;
        packet1.firmware_version = packet_in.firmware_version;
        packet1.firmware_git_hash = packet_in.firmware_git_hash;
        packet1.dialect_hash = packet_in.dialect_hash;
        packet1.samples = packet_in.samples;
        packet1.samples_dropped = packet_in.samples_dropped;
        packet1.frames_dropped = packet_in.frames_dropped;
        packet1.rejected_samples = packet_in.rejected_samples;
        packet1.crc_errors = packet_in.crc_errors;
        packet1.unknown_messages = packet_in.unknown_messages;
        packet1.param_rejects = packet_in.param_rejects;
        packet1.sensor_rate_requested = packet_in.sensor_rate_requested;
        packet1.sensor_rate_achieved = packet_in.sensor_rate_achieved;
        packet1.raw_rate_requested = packet_in.raw_rate_requested;
        packet1.raw_rate_achieved = packet_in.raw_rate_achieved;
        packet1.orientation_rate_requested = packet_in.orientation_rate_requested;
        packet1.orientation_rate_achieved = packet_in.orientation_rate_achieved;
        packet1.battery_voltage = packet_in.battery_voltage;
        packet1.cpu_load = packet_in.cpu_load;
        packet1.status_flags = packet_in.status_flags;
        packet1.battery_remaining = packet_in.battery_remaining;
        packet1.unit_id = packet_in.unit_id;
        packet1.filter_id = packet_in.filter_id;
        packet1.numeric_format = packet_in.numeric_format;
        packet1.earth_frame = packet_in.earth_frame;
        packet1.numeric_resets = packet_in.numeric_resets;
        packet1.hil_invalid = packet_in.hil_invalid;
        packet1.rejected_samples2 = packet_in.rejected_samples2;
        
        
#ifdef MAVLINK_STATUS_FLAG_OUT_MAVLINK1
        if (status->flags & MAVLINK_STATUS_FLAG_OUT_MAVLINK1) {
           // cope with extensions
           memset(MAVLINK_MSG_ID_KF_UNIT_STATUS_MIN_LEN + (char *)&packet1, 0, sizeof(packet1)-MAVLINK_MSG_ID_KF_UNIT_STATUS_MIN_LEN);
        }
#endif
        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_kf_unit_status_encode(system_id, component_id, &msg, &packet1);
    mavlink_msg_kf_unit_status_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_kf_unit_status_pack(system_id, component_id, &msg , packet1.time_boot_us , packet1.firmware_version , packet1.firmware_git_hash , packet1.dialect_hash , packet1.samples , packet1.samples_dropped , packet1.frames_dropped , packet1.rejected_samples , packet1.crc_errors , packet1.unknown_messages , packet1.param_rejects , packet1.sensor_rate_requested , packet1.sensor_rate_achieved , packet1.raw_rate_requested , packet1.raw_rate_achieved , packet1.orientation_rate_requested , packet1.orientation_rate_achieved , packet1.battery_voltage , packet1.cpu_load , packet1.status_flags , packet1.battery_remaining , packet1.unit_id , packet1.filter_id , packet1.numeric_format , packet1.earth_frame , packet1.numeric_resets , packet1.hil_invalid , packet1.rejected_samples2 );
    mavlink_msg_kf_unit_status_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_kf_unit_status_pack_chan(system_id, component_id, MAVLINK_COMM_0, &msg , packet1.time_boot_us , packet1.firmware_version , packet1.firmware_git_hash , packet1.dialect_hash , packet1.samples , packet1.samples_dropped , packet1.frames_dropped , packet1.rejected_samples , packet1.crc_errors , packet1.unknown_messages , packet1.param_rejects , packet1.sensor_rate_requested , packet1.sensor_rate_achieved , packet1.raw_rate_requested , packet1.raw_rate_achieved , packet1.orientation_rate_requested , packet1.orientation_rate_achieved , packet1.battery_voltage , packet1.cpu_load , packet1.status_flags , packet1.battery_remaining , packet1.unit_id , packet1.filter_id , packet1.numeric_format , packet1.earth_frame , packet1.numeric_resets , packet1.hil_invalid , packet1.rejected_samples2 );
    mavlink_msg_kf_unit_status_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
        mavlink_msg_to_send_buffer(buffer, &msg);
        for (i=0; i<mavlink_msg_get_send_buffer_length(&msg); i++) {
            comm_send_ch(MAVLINK_COMM_0, buffer[i]);
        }
    mavlink_msg_kf_unit_status_decode(last_msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);
        
        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_kf_unit_status_send(MAVLINK_COMM_1 , packet1.time_boot_us , packet1.firmware_version , packet1.firmware_git_hash , packet1.dialect_hash , packet1.samples , packet1.samples_dropped , packet1.frames_dropped , packet1.rejected_samples , packet1.crc_errors , packet1.unknown_messages , packet1.param_rejects , packet1.sensor_rate_requested , packet1.sensor_rate_achieved , packet1.raw_rate_requested , packet1.raw_rate_achieved , packet1.orientation_rate_requested , packet1.orientation_rate_achieved , packet1.battery_voltage , packet1.cpu_load , packet1.status_flags , packet1.battery_remaining , packet1.unit_id , packet1.filter_id , packet1.numeric_format , packet1.earth_frame , packet1.numeric_resets , packet1.hil_invalid , packet1.rejected_samples2 );
    mavlink_msg_kf_unit_status_decode(last_msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

#ifdef MAVLINK_HAVE_GET_MESSAGE_INFO
    MAVLINK_ASSERT(mavlink_get_message_info_by_name("KF_UNIT_STATUS") != NULL);
    MAVLINK_ASSERT(mavlink_get_message_info_by_id(MAVLINK_MSG_ID_KF_UNIT_STATUS) != NULL);
#endif
}

static void mavlink_test_kinefuse(uint8_t system_id, uint8_t component_id, mavlink_message_t *last_msg)
{
    mavlink_test_kf_raw_sample(system_id, component_id, last_msg);
    mavlink_test_kf_orientation(system_id, component_id, last_msg);
    mavlink_test_kf_joint_angle(system_id, component_id, last_msg);
    mavlink_test_kf_efforts(system_id, component_id, last_msg);
    mavlink_test_kf_unit_status(system_id, component_id, last_msg);
}

#ifdef __cplusplus
}
#endif // __cplusplus
#endif // KINEFUSE_TESTSUITE_H
