#pragma once
// The small part of the Garmin FIT profile that the reader maps: global message numbers,
// field numbers, scales, and the names of the enums it writes into the model. Numbers follow
// the public FIT profile (Profile.xlsx of the FIT SDK); everything else is skipped by size.

#include <cstdint>
#include <string>

namespace trailray::track::fit {

// Seconds from the Unix epoch to the FIT epoch (1989-12-31T00:00:00Z).
inline constexpr double kFitEpochUnix = 631065600.0;
// FIT date_time values below this are seconds since the device powered on, not UTC.
inline constexpr std::uint32_t kMinAbsoluteTime = 0x10000000;
// Degrees per semicircle: 2^31 semicircles make 180 degrees.
inline constexpr double kDegreesPerSemicircle = 180.0 / 2147483648.0;

// Field number of the timestamp, common to every message that has one.
inline constexpr std::uint8_t kFieldTimestamp = 253;

namespace msg {
inline constexpr std::uint16_t kFileId = 0;
inline constexpr std::uint16_t kDeviceSettings = 2;
inline constexpr std::uint16_t kSport = 12;
inline constexpr std::uint16_t kSession = 18;
inline constexpr std::uint16_t kLap = 19;
inline constexpr std::uint16_t kRecord = 20;
inline constexpr std::uint16_t kEvent = 21;
inline constexpr std::uint16_t kCourse = 31;
inline constexpr std::uint16_t kCoursePoint = 32;
inline constexpr std::uint16_t kLocation = 29;  // a saved place (Garmin's Locations.fit)
inline constexpr std::uint16_t kTimestampCorrelation = 162;
}  // namespace msg

namespace file_id {
inline constexpr std::uint8_t kType = 0;
inline constexpr std::uint8_t kManufacturer = 1;
inline constexpr std::uint8_t kProduct = 2;
inline constexpr std::uint8_t kSerialNumber = 3;
inline constexpr std::uint8_t kTimeCreated = 4;
inline constexpr std::uint8_t kProductName = 8;
}  // namespace file_id

namespace device_settings {
inline constexpr std::uint8_t kUtcOffset = 1;   // uint32: seconds added to system time to get UTC
inline constexpr std::uint8_t kTimeOffset = 2;  // uint32[]: seconds added to system time for local time
}  // namespace device_settings

namespace timestamp_correlation {
inline constexpr std::uint8_t kSystemTimestamp = 1;  // system time at the moment `timestamp` (UTC) was taken
}

namespace session {
inline constexpr std::uint8_t kStartTime = 2;
inline constexpr std::uint8_t kSport = 5;
inline constexpr std::uint8_t kSubSport = 6;
}  // namespace session

namespace sport {
inline constexpr std::uint8_t kSport = 0;
inline constexpr std::uint8_t kName = 3;
}  // namespace sport

namespace course {
inline constexpr std::uint8_t kSport = 4;
inline constexpr std::uint8_t kName = 5;
}  // namespace course

namespace course_point {
inline constexpr std::uint8_t kTimestamp = 1;
inline constexpr std::uint8_t kPositionLat = 2;
inline constexpr std::uint8_t kPositionLong = 3;
inline constexpr std::uint8_t kType = 5;
inline constexpr std::uint8_t kName = 6;
}  // namespace course_point

namespace location {
inline constexpr std::uint8_t kName = 0;
inline constexpr std::uint8_t kPositionLat = 1;
inline constexpr std::uint8_t kPositionLong = 2;
inline constexpr std::uint8_t kAltitude = 4;  // scale 5, offset 500, as a record's
inline constexpr std::uint8_t kDescription = 6;
}  // namespace location

namespace event {
inline constexpr std::uint8_t kEvent = 0;
inline constexpr std::uint8_t kEventType = 1;
inline constexpr std::uint8_t kEventTimer = 0;  // event value: the activity timer
inline constexpr std::uint8_t kTypeStart = 0;
inline constexpr std::uint8_t kTypeStop = 1;
inline constexpr std::uint8_t kTypeStopAll = 4;
}  // namespace event

namespace record {
inline constexpr std::uint8_t kPositionLat = 0;              // sint32 semicircles
inline constexpr std::uint8_t kPositionLong = 1;             // sint32 semicircles
inline constexpr std::uint8_t kAltitude = 2;                 // uint16, scale 5, offset 500 (m)
inline constexpr std::uint8_t kHeartRate = 3;                // uint8 bpm
inline constexpr std::uint8_t kCadence = 4;                  // uint8 rpm
inline constexpr std::uint8_t kSpeed = 6;                    // uint16, scale 1000 (m/s)
inline constexpr std::uint8_t kPower = 7;                    // uint16 W
inline constexpr std::uint8_t kCompressedSpeedDistance = 8;  // byte[3]: 12-bit speed (1/100 m/s), 12-bit distance
inline constexpr std::uint8_t kTemperature = 13;             // sint8 degrees C
inline constexpr std::uint8_t kEnhancedSpeed = 73;           // uint32, scale 1000 (m/s)
inline constexpr std::uint8_t kEnhancedAltitude = 78;        // uint32, scale 5, offset 500 (m)
inline constexpr double kAltitudeScale = 5.0;
inline constexpr double kAltitudeOffset = 500.0;
inline constexpr double kSpeedScale = 1000.0;
}  // namespace record

// Names of the enum values the reader writes out; an unknown value is written as its number.
std::string sport_name(std::uint64_t sport);
std::string course_point_type_name(std::uint64_t type);
std::string file_type_name(std::uint64_t type);
std::string manufacturer_name(std::uint64_t manufacturer);

}  // namespace trailray::track::fit
