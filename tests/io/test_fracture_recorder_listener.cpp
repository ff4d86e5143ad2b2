// SPDX-License-Identifier: Zlib
// The plumbing from a btFractureDynamicsWorld to the runner's records: a real fracture event
// (the plane-split stand-in engine breaking a glass slab under a steel ball) becomes one
// statistics row, and the fragments get the recorder's stable names and volumes, which the
// world's own fragment names follow.
#include "../coupling/CouplingScene.h"

#include <btFracture/io/FractureRecorder.h>
#include <btFracture/io/FractureRecorderListener.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace btfracture;

TEST(FractureRecorderListener, WorldEventsBecomeRowsAndStableNames) {
    const auto dir = std::filesystem::temp_directory_path() / "btfracture_test_recorder_listener";
    std::filesystem::create_directories(dir);
    const std::string csv = (dir / "statistics.csv").string();
    {
        FractureRecorder recorder(csv);
        FractureRecorderListener listener(recorder, test::kStep);
        test::Scene scene;
        listener.addOriginal(*scene.slab, "pane");
        scene.world->addFractureListener(&listener);
        const double slabVolume = scene.slab->volume();
        const std::string slabName = scene.slab->name();
        for (int i = 0; i < 60 && recorder.events() == 0; ++i) scene.step();
        ASSERT_GE(recorder.events(), 1) << "the ball did not break the slab";

        const auto fragments = recorder.fragments();
        ASSERT_EQ(fragments.size(), 2u);  // a plane split: two halves
        EXPECT_EQ(fragments[0].name, "pane_f1");
        EXPECT_EQ(fragments[1].name, "pane_f2");
        // The halves add up to the slab (volumes measured on the closed fragment meshes).
        EXPECT_NEAR(fragments[0].volume + fragments[1].volume, slabVolume, 1e-9 * slabVolume);
        EXPECT_NEAR(fragments[0].relativeVolume + fragments[1].relativeVolume, 1.0, 1e-9);
        // The world's fragment bodies answer to the recorder's names.
        std::vector<std::string> names;
        for (btFractureRigidBody* f : scene.fragments()) names.push_back(listener.nameOf(f));
        EXPECT_EQ(names, (std::vector<std::string>{"pane_f1", "pane_f2"}));
        // The world names them the same way after their root body (the runner's bodies have
        // their output names).
        for (std::size_t k = 0; k < scene.fragments().size(); ++k) {
            EXPECT_EQ(scene.fragments()[k]->name(), slabName + "_f" + std::to_string(k + 1));
            EXPECT_EQ(scene.fragments()[k]->rootName(), slabName);
        }
        EXPECT_EQ(listener.nameOf(scene.ball.get()), "");
        scene.world->removeFractureListener(&listener);
        recorder.close();
    }
    std::ifstream in(csv);
    std::string header, row;
    std::getline(in, header);
    std::getline(in, row);
    EXPECT_EQ(row.rfind("1,", 0), 0u) << row;
    EXPECT_NE(row.find(",pane,"), std::string::npos) << row;
    EXPECT_NE(row.find(",hybrid,1000,0,2,pane_f1 pane_f2,"), std::string::npos) << row;
}
