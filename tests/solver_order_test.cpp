// The order in which the solver sweeps its contacts (orderContacts): top layers first, contacts with
// infinite mass last, each circle's first contact before any circle's second, and within those the
// contacts that were pushing at the end of the last step before the others.
#include "solver_narrowphase.hpp" // internal: tests may reach inside, users may not

#include <catch2/catch.hpp>

#include <vector>

using namespace rube;

namespace {

/// A contact from circle a to body b, warm started with `impulse`, tagged by `id` in its record.
void addContact(std::vector<ContactConstraint>& contacts, std::vector<ContactRecord>& records, int a, int b,
                double impulse, int id) {
    ContactConstraint c;
    c.a = a;
    c.b = b;
    c.normal = {0.0, 1.0};
    c.impulse = impulse;
    c.normalMass = id; // the contact carries its tag too, to check records move with their contacts
    contacts.push_back(c);
    ContactRecord r;
    r.touchTime = id;
    records.push_back(r);
}

} // namespace

TEST_CASE("contacts are swept top layer first, by rank, pushing before not, infinite mass last", "[solver][order]") {
    // Circles 0-3 on the floor layer, 4 and 5 high above; body 6 is a segment (infinite mass).
    const std::vector<Vec2> positions{{0.0, 0.0}, {0.2, 0.0}, {0.4, 0.0}, {0.6, 0.0}, {0.0, 5.0}, {0.2, 5.0}};
    const std::vector<double> inverseMass{1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 0.0};
    std::vector<ContactConstraint> contacts;
    std::vector<ContactRecord> records;
    addContact(contacts, records, 0, 1, 0.0, 0); // circle 0's first contact: not pushing
    addContact(contacts, records, 2, 3, 0.5, 1); // circle 2's first: pushing
    addContact(contacts, records, 0, 6, 0.2, 2); // circle 0's second, against the segment
    addContact(contacts, records, 1, 2, 0.1, 3); // circle 1's first: pushing
    addContact(contacts, records, 0, 2, 0.0, 4); // circle 0's third
    addContact(contacts, records, 4, 5, 0.0, 5); // the top layer
    ContactOrderScratch scratch;
    orderContacts(contacts, records, positions, inverseMass, {0.0, 1.0}, 0.5, scratch);

    // Top layer; then the floor layer's first contacts, pushing (1, 3, in their old order) before not
    // (0); then its third contacts (4); the segment's last. Without the pushing split: 5, 0, 1, 3, 4, 2.
    const std::vector<int> expected{5, 1, 3, 0, 4, 2};
    REQUIRE(contacts.size() == expected.size());
    for (std::size_t k = 0; k < expected.size(); ++k) {
        INFO("position " << k);
        CHECK(static_cast<int>(contacts[k].normalMass) == expected[k]);
        CHECK(static_cast<int>(records[k].touchTime) == expected[k]);
    }
}
