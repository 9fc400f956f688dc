; A rover (planar disk) in the west room must image the crater from the
; east room (after calibrating at the calibration target there), bring the
; east room's rock to the lander's pad in the west room, and send the image
; from the lander. Path costs: cm, room to room through the doorway.
(define (problem b28-p01)
  (:domain b28-rovers)
  (:objects start-wp lander-wp cal-wp view-wp rock-wp - waypoint
            rock-bed lander-pad - pad
            rock1 - rock
            crater - objective)
  (:init (rover-at start-wp) (store-empty)
         (rock-in rock1 rock-bed) (near rock-bed rock-wp)
         (near lander-pad lander-wp) (is-lander lander-pad)
         (cal-from cal-wp) (visible-from crater view-wp) (comm-from lander-wp)
         (link start-wp lander-wp) (link lander-wp start-wp)
         (link start-wp cal-wp) (link cal-wp start-wp)
         (link start-wp view-wp) (link view-wp start-wp)
         (link start-wp rock-wp) (link rock-wp start-wp)
         (link lander-wp cal-wp) (link cal-wp lander-wp)
         (link lander-wp view-wp) (link view-wp lander-wp)
         (link lander-wp rock-wp) (link rock-wp lander-wp)
         (link cal-wp view-wp) (link view-wp cal-wp)
         (link cal-wp rock-wp) (link rock-wp cal-wp)
         (link view-wp rock-wp) (link rock-wp view-wp)
         (= (path-cost start-wp lander-wp) 34) (= (path-cost lander-wp start-wp) 34)
         (= (path-cost start-wp cal-wp) 109) (= (path-cost cal-wp start-wp) 109)
         (= (path-cost start-wp view-wp) 140) (= (path-cost view-wp start-wp) 140)
         (= (path-cost start-wp rock-wp) 153) (= (path-cost rock-wp start-wp) 153)
         (= (path-cost lander-wp cal-wp) 80) (= (path-cost cal-wp lander-wp) 80)
         (= (path-cost lander-wp view-wp) 111) (= (path-cost view-wp lander-wp) 111)
         (= (path-cost lander-wp rock-wp) 124) (= (path-cost rock-wp lander-wp) 124)
         (= (path-cost cal-wp view-wp) 30) (= (path-cost view-wp cal-wp) 30)
         (= (path-cost cal-wp rock-wp) 57) (= (path-cost rock-wp cal-wp) 57)
         (= (path-cost view-wp rock-wp) 52) (= (path-cost rock-wp view-wp) 52)
         (= (total-cost) 0))
  (:goal (and (communicated crater) (rock-in rock1 lander-pad)))
  (:metric minimize (total-cost)))
