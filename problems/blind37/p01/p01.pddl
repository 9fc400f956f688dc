; blind37 p01: build plate / drum / cube on the dais's goal region; the cube starts on the plate.
; Expected 8 actions: unstack cube, put it down, plate to goal, drum on plate, cube on drum.
(define (problem p01)
  (:domain tower-strips)
  (:objects plate drum cube left right park goal)
  (:init (block plate) (block drum) (block cube)
         (region left) (region right) (region park) (region goal)
         (on-table plate left) (on cube plate) (on-table drum right)
         (clear cube) (clear drum) (handempty))
  (:goal (and (on-table plate goal) (on drum plate) (on cube drum))))
