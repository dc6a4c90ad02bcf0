// The paper's rule for a grain that carries load (section 3.1): it needs at
// least this many contacts; with fewer it lies loose. One definition for the
// compute's classification (its default min_contacts, loaded contacts) and
// the fix's count of the grains with few contacts before loading (touching
// grains and walls).
#ifndef FABRIC_MIN_CONTACTS_H
#define FABRIC_MIN_CONTACTS_H

namespace fabric {

constexpr int kMinContacts = 3;

}  // namespace fabric

#endif
