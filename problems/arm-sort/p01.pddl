; Two red and two blue cubes into the bins of their colour: 8 actions.
(define (problem arm-sort-p01)
  (:domain arm-sort)
  (:objects red1 red2 blue1 blue2 - block
            workspace red-bin blue-bin - region)
  (:init (at red1 workspace) (at red2 workspace)
         (at blue1 workspace) (at blue2 workspace) (handempty))
  (:goal (and (at red1 red-bin) (at red2 red-bin)
              (at blue1 blue-bin) (at blue2 blue-bin))))
